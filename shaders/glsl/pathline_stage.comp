#version 460
// The RK4 arithmetic of pathlines on the device, one stage per dispatch (shared/pathline_stage.h):
// between two dispatches the backend's probe kernels sample snapshot A at cellsA and B at cellsB
// (include/locate_probe.glsl); a stage combines the two samples at the stage's time, as
// PathlineTracer::sampleAt does, takes the stage's k and places the next sample point. Twin of
// PathlineTracer::move (src/flow/pathline_tracer.cpp), in the same float operations.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/pathline_stage.h"
#include "shared/trace_codes.h"

layout(push_constant, scalar) uniform PushBlock { PathlineStagePush pc; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_INTERVAL)
uniform IntervalBlock { PathlineInterval interval; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_SCHEDULE)
readonly buffer ScheduleBuffer { PathlineStep schedule[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_GROUPS)
readonly buffer GroupBuffer { uint groups[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_POSITIONS)
buffer PositionBuffer { vec3 positions[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_REASONS)
buffer ReasonBuffer { int reasons[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_STAGES)
buffer StageBuffer { vec3 stages[]; };  // 4 per particle: k1, k2, k3, the step's end point
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_STEP_REASONS)
buffer StepReasonBuffer { int stepReasons[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_CELLS_A)
writeonly buffer CellsABuffer { vec3 cellsA[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_CELLS_B)
writeonly buffer CellsBBuffer { vec3 cellsB[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_VECTORS_A)
readonly buffer VectorsABuffer { vec3 vectorsA[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_VECTORS_B)
readonly buffer VectorsBBuffer { vec3 vectorsB[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_REGIONS_A)
readonly buffer RegionsABuffer { int regionsA[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_REGIONS_B)
readonly buffer RegionsBBuffer { int regionsB[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_OUT_POSITIONS)
writeonly buffer OutPositionBuffer { vec3 outPositions[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_OUT_VECTORS)
writeonly buffer OutVectorBuffer { vec3 outVectors[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_PATHLINE_OUT_STATUS)
writeonly buffer OutStatusBuffer { int outStatus[]; };

layout(local_size_x = AMRSTREAM_PATHLINE_GROUP) in;

// Outside every domain: the probes find no region there at once.
const vec3 kNowhere = vec3(1e30);

// x in the frame's cell units, moved by whole periods into its domain along periodic axes; twin
// of cellOf() in pathline_tracer.cpp (which works in double).
vec3 cellsOf(PathlineFrame f, vec3 x) {
  precise vec3 c = (x - f.origin) / f.spacing;
  for (int axis = 0; axis < 3; ++axis) {
    if ((f.periodicAxes & (1u << axis)) == 0u) continue;
    const float cell = floor(c[axis]);
    const float period = float(f.domainUpper[axis] - f.domainLower[axis]);
    if (cell >= float(f.domainUpper[axis]))
      c[axis] -= period;
    else if (cell < float(f.domainLower[axis]))
      c[axis] += period;
  }
  return c;
}

// Twin of wrapPhysical(): x moved by whole periods into A's domain.
vec3 wrapPhysical(PathlineFrame f, vec3 x) {
  if (f.periodicAxes == 0u) return x;
  precise const vec3 wrapped = f.origin + f.spacing * cellsOf(f, x);
  return wrapped;
}

void placeSample(uint i, vec3 x) {
  cellsA[i] = cellsOf(interval.a, x);
  cellsB[i] = cellsOf(interval.b, x);
}

void placeNothing(uint i) {
  cellsA[i] = kNowhere;
  cellsB[i] = kNowhere;
}

// The vector at the probed point at time weight w of B, and the reason the sample fails
// (AMRSTREAM_REASON_RUNNING where it does not); zero where it fails, as on the CPU.
vec3 sampleAtTime(uint i, float w, out int reason) {
  reason = AMRSTREAM_REASON_RUNNING;
  if (regionsA[i] < 0 || regionsB[i] < 0) {
    reason = AMRSTREAM_REASON_OUT_OF_DOMAIN;
    return vec3(0.0);
  }
  const vec3 a = vectorsA[i], b = vectorsB[i];
  if (any(isnan(a)) || any(isnan(b))) {
    reason = AMRSTREAM_REASON_UNEXPECTED_VALUE;
    return vec3(0.0);
  }
  precise const vec3 v = a + w * (b - a);
  return v;
}

void noteReason(uint i, int reason) {
  if (stepReasons[i] == AMRSTREAM_REASON_RUNNING) stepReasons[i] = reason;
}

// k1 from the vector at the step's start, and the point of k2's sample.
void beginStep(uint i, vec3 x, float h, vec3 v, int reason) {
  stepReasons[i] = reason;
  precise const vec3 k1 = h * v;
  stages[4u * i] = k1;
  precise const vec3 p = x + 0.5 * k1;
  placeSample(i, p);
}

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= interval.particleCount) return;
  const uint first = groups[i] * interval.stepCount;
  const PathlineStep s = schedule[first + pc.step];
  const uint slot = pc.row * interval.particleCount + i;
  if (reasons[i] != AMRSTREAM_REASON_RUNNING || s.taken == 0u) {
    placeNothing(i);
    if (pc.stage == AMRSTREAM_PATHLINE_END) outStatus[slot] = AMRSTREAM_PATHLINE_NO_STEP;
    return;
  }
  const vec3 x = positions[i];
  if (pc.stage == AMRSTREAM_PATHLINE_START) {
    placeSample(i, x);
    return;
  }
  int reason;
  if (pc.stage == AMRSTREAM_PATHLINE_K1) {
    beginStep(i, x, s.h, sampleAtTime(i, s.weightStart, reason), reason);
    return;
  }
  if (pc.stage == AMRSTREAM_PATHLINE_K2 || pc.stage == AMRSTREAM_PATHLINE_K3) {
    precise const vec3 k = s.h * sampleAtTime(i, s.weightHalf, reason);
    noteReason(i, reason);
    stages[4u * i + pc.stage - AMRSTREAM_PATHLINE_K1] = k;
    precise const vec3 p = x + (pc.stage == AMRSTREAM_PATHLINE_K2 ? 0.5 : 1.0) * k;
    placeSample(i, p);
    return;
  }
  if (pc.stage == AMRSTREAM_PATHLINE_K4) {
    precise const vec3 k4 = s.h * sampleAtTime(i, s.weightFull, reason);
    noteReason(i, reason);
    precise const vec3 moved =
        x + (stages[4u * i] + 2.0 * stages[4u * i + 1u] + 2.0 * stages[4u * i + 2u] + k4) / 6.0;
    const vec3 end = wrapPhysical(interval.a, moved);
    stages[4u * i + 3u] = end;
    placeSample(i, end);
    return;
  }
  // AMRSTREAM_PATHLINE_END: the sample at the new point stops the particle where it fails, as an
  // earlier stage's failure does; else it is the point's vector and the next step's start.
  const vec3 v = sampleAtTime(i, s.weightEnd, reason);
  const int stop = stepReasons[i] != AMRSTREAM_REASON_RUNNING ? stepReasons[i] : reason;
  outStatus[slot] = stop;
  if (stop != AMRSTREAM_REASON_RUNNING) {
    reasons[i] = stop;
    placeNothing(i);
    return;
  }
  const vec3 end = stages[4u * i + 3u];
  positions[i] = end;
  outPositions[slot] = end;
  outVectors[slot] = v;
  const uint next = pc.step + 1u;
  if (next < interval.stepCount && schedule[first + next].taken != 0u)
    beginStep(i, end, schedule[first + next].h, v, AMRSTREAM_REASON_RUNNING);
  else
    placeNothing(i);
}
