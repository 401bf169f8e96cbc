// Parameters of one tracing round, shared by the host and the GLSL kernels (scalar layout).
// Positions are in finest-cell units; velocities and cell widths physical (see
// src/flow/line_tracer.cpp, the CPU twin of include/line_round.glsl).
#ifndef AMRSTREAM_SHARED_TRACE_PARAMS_H
#define AMRSTREAM_SHARED_TRACE_PARAMS_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

struct TraceParams {
  ivec3 domainLower;  // the cells' bounding box [domainLower, domainUpper)
  uint lineCount;     // lines advanced by this round (one thread each)
  ivec3 domainUpper;
  uint roundSteps;          // steps a line may take in this round before it pauses
  vec3 cellsPerPhysical;    // 1 / spacing
  float physicalCellWidth;  // smallest spacing: physical width of a finest cell
  vec3 spacing;
  int stepMode;       // AMRSTREAM_STEP_*
  ivec3 period;       // domainUpper - domainLower: the period of periodic axes
  uint periodicAxes;  // bit a set: axis a is periodic (positions wrap into the domain)
  float stepSize;
  uint maxSteps;
  float terminalSpeed;
  float maxLength;         // physical arc length limit; 0: none
  float maxTime;           // |IntegrationTime| limit; 0: none
  uint keepHistory;        // 0: emit only each line's last point, when it ends
  uint pointsPerLine;      // output slots per line in this round: roundSteps + 1, or 1
  uint linearInterpolant;  // 1: tent weights over the cells' linear models (vectorGradients)
  int integrator;          // AMRSTREAM_INTEGRATOR_*
  float toleranceSquared;  // rk45: the square of the error allowed per step, in cell widths
  float minStep;           // rk45: bounds of the adaptive step, in the units of stepSize
  float maxStep;
  uint deepPositions;  // 1: domains wider than 2^21 finest cells (VectorVolume::deepPositions):
                       // anchors follow the lines, points leave as offsets from their regions
  vec3 pauseLower;     // with pauseOutside, a line pauses after a step that ends outside
  uint pauseOutside;   // [pauseLower, pauseUpper) (finest-cell units), to be handed to the
  vec3 pauseUpper;     // MPI rank that holds where it is (tracing over data)
  uvec2 dualValuesAddress;  // the dual cells' device address, low word first, for kernels that
                            // read them so (VolumeBuffers::dualValuesAddress); 0 otherwise
  uint laneShift;           // 2^laneShift invocations a line, the first of them tracing it
};

#ifdef __cplusplus
static_assert(sizeof(TraceParams) == 172 && offsetof(TraceParams, period) == 64 &&
              offsetof(TraceParams, maxTime) == 96 && offsetof(TraceParams, pauseOutside) == 144);
}  // namespace amrstream::shared
#endif

#endif
