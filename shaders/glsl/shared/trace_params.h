// Parameters of one tracing dispatch, shared by the host and the GLSL kernels (scalar layout).
// Positions are in finest-cell units; velocities and cell widths physical (see
// src/flow/integrator.cpp, the CPU twin of include/integrator.glsl).
#ifndef AMRSTREAM_SHARED_TRACE_PARAMS_H
#define AMRSTREAM_SHARED_TRACE_PARAMS_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

struct TraceParams {
  ivec3 domainLower;      // the cells' bounding box [domainLower, domainUpper)
  uint seedCount;
  ivec3 domainUpper;
  uint capacity;          // points stored per trace: max steps + 1, or 1 without history
  vec3 cellsPerPhysical;  // 1 / spacing
  float physicalCellWidth;  // smallest spacing: physical width of a finest cell
  vec3 spacing;
  int stepMode;           // AMRSTREAM_STEP_*
  float stepSize;
  uint maxSteps;
  float terminalSpeed;
  float maxLength;        // 0: no limit
  uint keepHistory;       // 0: store only each trace's last point (endpoints-only)
};

#ifdef __cplusplus
static_assert(sizeof(TraceParams) == 84 && offsetof(TraceParams, spacing) == 48 &&
              offsetof(TraceParams, maxLength) == 76);
}  // namespace amrstream::shared
#endif

#endif
