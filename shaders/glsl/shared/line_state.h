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

struct LineState {
  vec3 position;    // finest-cell units, inside the domain (wrapped on periodic axes)
  float time;       // IntegrationTime so far: negative when tracing backward
  float arcLength;  // physical arc length so far
  uint steps;       // integration steps taken so far
  uint line;        // the line's index in the output
  float direction;  // +1 forward, -1 backward
  float stepSize;   // rk45: the step the next step tries first; 0: params.stepSize
};

// One per line advanced by a round, in thread order.
struct LineRound {
  uint line;
  uint points;  // points the line emitted in this round
  uint steps;   // integration steps taken in all rounds so far
  int reason;   // AMRSTREAM_REASON_RUNNING while the line goes on
};

// One emitted point of a round, before the point data: position in cell units, IntegrationTime,
// the vector sampled there and the region that sample found (-1: none).
#define AMRSTREAM_NO_REGION_ID (-1)

#ifdef __cplusplus
static_assert(sizeof(LineState) == 36 && offsetof(LineState, line) == 24);
static_assert(sizeof(LineRound) == 16);
}  // namespace amrstream::shared
#endif

#endif
