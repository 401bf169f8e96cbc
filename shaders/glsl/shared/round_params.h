// Push constants of the kernels that follow a tracing round: the compaction of its output
// (include/compaction.glsl) and the point data sampled at the compacted points
// (point_data.comp). Scalar layout, shared with the host.
#ifndef AMRSTREAM_SHARED_ROUND_PARAMS_H
#define AMRSTREAM_SHARED_ROUND_PARAMS_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

struct CompactionParams {
  uint lineCount;      // lines the round advanced
  uint pointsPerLine;  // the round's output slots per line (point k of line t at k * lineCount + t)
};

struct PointDataParams {
  vec3 cellsPerPhysical;   // 1 / spacing: derivatives in cell units to physical ones
  uint channelCount;       // scalar channels sampled at every point
  uint computeVorticity;   // 1: the curl of the reconstructed vector as well
  uint linearInterpolant;  // 1: tent weights over the cells' linear models (the gradients)
  uint deepPositions;      // 1: positions are offsets from their regions' corners (line_state.h)
};

// The totals of a round's compaction, written by the device for the host and for the indirect
// dispatch of the point data kernel.
struct RoundSummary {
  uint points;        // points emitted by all lines
  uint liveLines;     // lines still running
  uvec3 pointGroups;  // workgroups of the point data kernel: (ceil(points / 64), 1, 1)
};

#define AMRSTREAM_COMPACTION_GROUP 256
#define AMRSTREAM_POINT_DATA_GROUP 64

#ifdef __cplusplus
static_assert(sizeof(CompactionParams) == 8 && sizeof(PointDataParams) == 28 &&
              sizeof(RoundSummary) == 20);
}  // namespace amrstream::shared
#endif

#endif
