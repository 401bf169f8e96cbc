// The pathline stage kernel (pathline_stage.comp) and its host (src/gpu/pathline_stepper.cpp):
// the RK4 arithmetic of pathlines between the point-location probes that sample the two
// snapshots of an interval, all on the device (docs/architecture.md, "Pathlines"). Scalar
// layout, shared with the host.
#ifndef AMRSTREAM_SHARED_PATHLINE_STAGE_H
#define AMRSTREAM_SHARED_PATHLINE_STAGE_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

// One step of the particles of one group (those at one time when the interval starts): the
// step and the weights w = (t - tA) / (tB - tA) of snapshot B at its stages' times, computed in
// double on the host as the CPU tracer computes them.
struct PathlineStep {
  float h;            // the step, physical time
  float weightStart;  // at the step's start, t: the interval's first step samples there
  float weightHalf;   // at t + h / 2 (k2, k3)
  float weightFull;   // at t + h (k4)
  float weightEnd;    // at the step's end time (t + h, or tB when it ends the interval)
  uint taken;         // 0: the group takes no step here
};

// A snapshot's cell units (the WorldTransform in float) and its domain, for the probes' points
// and the wrap along periodic axes.
struct PathlineFrame {
  vec3 origin;
  uint periodicAxes;  // bit a set: axis a is periodic
  vec3 spacing;
  float unused0;
  ivec3 domainLower;
  uint unused1;
  ivec3 domainUpper;
  uint unused2;
};

// The interval (uniform).
struct PathlineInterval {
  PathlineFrame a, b;
  uint particleCount;
  uint stepCount;  // steps per group in the schedule: group g's step j at g * stepCount + j
  uint unused0, unused1;
};

// Push constants of one dispatch.
struct PathlineStagePush {
  uint stage;  // AMRSTREAM_PATHLINE_*
  uint step;   // the step of the interval
  uint row;    // the step's row in this round's output
};

// The stages: the start point's cells; then each combines the two snapshots' samples at the
// stage's point and places the next point.
#define AMRSTREAM_PATHLINE_START 0u  // the points of the interval's first samples
#define AMRSTREAM_PATHLINE_K1 1u
#define AMRSTREAM_PATHLINE_K2 2u
#define AMRSTREAM_PATHLINE_K3 3u
#define AMRSTREAM_PATHLINE_K4 4u
// The sample at the step's end: the point emitted (or the reason the particle stops), and the
// next step's k1 from the same sample.
#define AMRSTREAM_PATHLINE_END 5u

// A step's status in the output: a reason (AMRSTREAM_REASON_RUNNING: a point was emitted), or:
#define AMRSTREAM_PATHLINE_NO_STEP (-1)

#define AMRSTREAM_PATHLINE_GROUP 256

#define AMRSTREAM_BINDING_PATHLINE_INTERVAL 0      // the uniform PathlineInterval
#define AMRSTREAM_BINDING_PATHLINE_SCHEDULE 1      // PathlineStep[groups * stepCount]
#define AMRSTREAM_BINDING_PATHLINE_GROUPS 2        // uint per particle
#define AMRSTREAM_BINDING_PATHLINE_POSITIONS 3     // vec3 per particle: where its step starts
#define AMRSTREAM_BINDING_PATHLINE_REASONS 4       // int per particle: 0 while it runs
#define AMRSTREAM_BINDING_PATHLINE_STAGES 5        // per particle k1, k2, k3, the step's end point
#define AMRSTREAM_BINDING_PATHLINE_STEP_REASONS 6  // int per particle: the step's first failure
#define AMRSTREAM_BINDING_PATHLINE_CELLS_A 7       // vec3: the next sample's point in A's cells
#define AMRSTREAM_BINDING_PATHLINE_CELLS_B 8
#define AMRSTREAM_BINDING_PATHLINE_VECTORS_A 9  // vec3: A's sample there (NaN: invalid)
#define AMRSTREAM_BINDING_PATHLINE_VECTORS_B 10
#define AMRSTREAM_BINDING_PATHLINE_REGIONS_A 11  // int: A's region there (-1: none)
#define AMRSTREAM_BINDING_PATHLINE_REGIONS_B 12
#define AMRSTREAM_BINDING_PATHLINE_OUT_POSITIONS 13  // per row and particle: the emitted point
#define AMRSTREAM_BINDING_PATHLINE_OUT_VECTORS 14
#define AMRSTREAM_BINDING_PATHLINE_OUT_STATUS 15
#define AMRSTREAM_PATHLINE_BINDING_COUNT 16

#ifdef __cplusplus
static_assert(sizeof(PathlineStep) == 24 && sizeof(PathlineFrame) == 64 &&
              sizeof(PathlineInterval) == 144 && sizeof(PathlineStagePush) == 12);
}  // namespace amrstream::shared
#endif

#endif
