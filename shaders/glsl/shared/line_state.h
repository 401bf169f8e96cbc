// What a streamline carries from one tracing round to the next, and what a round reports per
// line; shared by the host and the GLSL kernels (scalar layout). A line is one seed traced in
// one direction. The fixed-step integrators keep no state between steps but the point and rk45
// only its next step, so a line continued in the next round is the same line as one traced in
// one go.
#ifndef AMRSTREAM_SHARED_LINE_STATE_H
#define AMRSTREAM_SHARED_LINE_STATE_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

// The line's point is anchor + offset (finest-cell units, inside the domain, wrapped on periodic
// axes); after every step the whole cells of offset move into anchor, so offset is in [0, 1).
struct LineState {
  vec3 offset;
  float time;       // IntegrationTime so far: negative when tracing backward
  float arcLength;  // physical arc length so far
  uint steps;       // integration steps taken so far
  uint line;        // the line's index in the output
  float direction;  // +1 forward, -1 backward
  float stepSize;   // rk45: the step the next step tries first; 0: params.stepSize
  ivec3 anchor;
};

// One per line advanced by a round, in thread order.
struct LineRound {
  uint line;
  uint points;  // points the line emitted in this round
  uint steps;   // integration steps taken in all rounds so far
  int reason;   // AMRSTREAM_REASON_RUNNING while the line goes on
};

// One emitted point of a round, before the point data: its position in cell units or, with
// params.deepPositions (domains wider than 2^21 finest cells), as an offset from the lower corner
// of the region its sample found (regionCorner(), so that it keeps float precision at any depth;
// from the origin with no region); IntegrationTime; the vector sampled there; and that region.
#define AMRSTREAM_NO_REGION_ID (-1)

#ifdef __cplusplus
static_assert(sizeof(LineState) == 48 && offsetof(LineState, line) == 24 &&
              offsetof(LineState, anchor) == 36);
static_assert(sizeof(LineRound) == 16);
}  // namespace amrstream::shared
#endif

#endif
