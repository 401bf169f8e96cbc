// One tracing round of one line: at most params.roundSteps steps of the integrator with the step
// mode's direction scaling, VTK termination codes, periodic wrapping and the --max-time
// shortening of the last step; twin of src/flow/line_tracer.cpp (advanceLine). Needs
// sampler.glsl.
#extension GL_EXT_control_flow_attributes : require

// `precise` throughout, as in sampler.glsl: no FMA contraction, like the CPU reference.
// parameterStep() is the advance of |IntegrationTime| for step h, direction() the stage vector
// (the displacement in cell units that step h would make with that sample's velocity).
float parameterStep(VectorSample s, float h) {
  precise const float step = params.stepMode == AMRSTREAM_STEP_TIME
                                 ? h
                                 : h * s.cellWidth * params.physicalCellWidth;
  return step;
}

vec3 direction(VectorSample s, float h) {
  precise vec3 v = s.value;
  if (params.stepMode == AMRSTREAM_STEP_ARC) {
    precise const float speed = length(v);
    v = speed > 0.0 ? v / speed : vec3(0.0);
  }
  precise const vec3 k = parameterStep(s, h) * v * params.cellsPerPhysical;
  return k;
}

int sampleFailure(VectorSample s) {
  if (!s.located) return AMRSTREAM_REASON_OUT_OF_DOMAIN;
  if (!s.valid) return AMRSTREAM_REASON_UNEXPECTED_VALUE;
  return AMRSTREAM_REASON_RUNNING;
}

// The anchor of the line being advanced: the steps work on offsets from it, and it moves only
// between steps (cell_point.glsl).
ivec3 lineAnchor;

// Without deep positions the anchor stays zero, and a point that leaves the domain along a
// periodic axis moves by the period in float; twin of wrapCellUnits() in line_tracer.cpp.
vec3 wrapCellUnits(vec3 p) {
  if (params.periodicAxes == 0u) return p;
  precise vec3 q = p;
  for (int a = 0; a < 3; ++a) {
    if ((params.periodicAxes & (1u << a)) == 0u) continue;
    const float lower = float(params.domainLower[a]), upper = float(params.domainUpper[a]);
    if (q[a] >= upper)
      q[a] -= float(params.period[a]);
    else if (q[a] < lower)
      q[a] += float(params.period[a]);
    if (q[a] >= upper) q[a] = lower;  // a point just below the lower face rounded onto the upper
  }
  return q;
}

// Twin of TraceOptions::Box::contains() (src/flow/integrator.hpp), negated.
bool outsidePauseBox(vec3 x) {
  precise const vec3 p = vec3(lineAnchor) + x;
  return any(lessThan(p, params.pauseLower)) || any(greaterThanEqual(p, params.pauseUpper));
}

// A stage's sample at x + k (`end` false), or a step's end point (`end` true), sampled where the
// next step starts from it: with the offset's whole cells moved into the anchor (twin of
// normalized()). One call of sampleVector either way.
VectorSample samplePoint(vec3 unwrapped, bool end) {
  ivec3 anchor = ivec3(0);
  precise vec3 offset = unwrapped;
  if (!kDeepPositions) {
    offset = wrapCellUnits(unwrapped);
  } else if (end && isNear(unwrapped)) {
    const vec3 whole = floor(unwrapped);
    offset = unwrapped - whole;
    anchor = wrapPeriodic(lineAnchor + ivec3(whole), offset);
  } else {
    anchor = wrapPeriodic(lineAnchor, unwrapped);
  }
  return sampleVector(anchor, offset);
}

VectorSample sampleStage(vec3 unwrapped) { return samplePoint(unwrapped, false); }
VectorSample sampleEnd(vec3 unwrapped) { return samplePoint(unwrapped, true); }

// What one step did; twin of flow::StepOutcome (src/flow/line_steps.hpp).
struct StepOutcome {
  int reason;          // AMRSTREAM_REASON_RUNNING when the step was taken
  vec3 unwrapped;      // x plus the step's displacement
  VectorSample next;   // the sample at the wrapped end point
  float step;          // the step taken
  float nextStep;      // rk45: the step to try next
};

// The integrator is baked into the pipeline (specialization constant 2), so a kernel holds only
// its own step's registers.
layout(constant_id = 2) const int kIntegrator = AMRSTREAM_INTEGRATOR_RK4;

// RK4's samples in one loop (rk4Step) or written out (advanceLine), the same sums in the same
// order either way. The pipeline kernel always loops (every traceRayEXT is a point the shader
// resumes from); the compute kernels loop where specialization constant 5 says so: on CPU
// devices, whose compiler then has one sample's code to compile instead of four.
#ifdef AMRSTREAM_RK4_SAMPLE_LOOP
const bool kRk4SampleLoop = true;
#else
layout(constant_id = 5) const bool kRk4SampleLoop = false;
#endif

#include "euler_step.glsl"
#include "rk2_step.glsl"
#include "rk45_step.glsl"

// Outputs are point-major: point k of thread t is at slot k * lineCount + t, so the invocations
// of a subgroup write one step's points to neighbouring slots. The compaction kernels gather them.
// Positions leave in cell units, or as offsets from their regions' corners (line_state.h).
void emitPoint(uint thread, uint k, vec3 x, float time, VectorSample s) {
  const uint slot = k * params.lineCount + thread;
  const ivec3 corner = params.deepPositions != 0u && s.region >= 0
                           ? regionCorner(regions[s.region].lower)
                           : ivec3(0);
  precise const vec3 position = vec3(lineAnchor - corner) + x;
  outPositions[slot] = position;
  outTimes[slot] = time;
  outVectors[slot] = s.value;
  outRegions[slot] = s.region;
}

// A line between two steps of its round: the offset x from lineAnchor, its IntegrationTime and
// arc length, its steps and the points this round emitted, rk45's next step and the sample at x.
// Not `precise` (a struct's members take no such qualifier): every value computed into it is
// computed into a precise variable first.
struct LineProgress {
  vec3 x;
  float time;
  float traceLength;
  uint steps;
  uint emitted;
  float nextStep;
  VectorSample s;
};

void emitLinePoint(uint thread, inout LineProgress line) {
  emitPoint(thread, line.emitted++, line.x, line.time, line.s);
}

// The line where the last round left it, sampled, its first point emitted if it has no step yet.
LineProgress resumeLine(uint thread, LineState state) {
  lineAnchor = kDeepPositions ? state.anchor : ivec3(0);
  // rk45's next step; the fixed-step kernels keep none, so it holds no register there.
  const float nextStep = kIntegrator == AMRSTREAM_INTEGRATOR_RK45 ? state.stepSize : 0.0;
  LineProgress line = LineProgress(state.offset, state.time, state.arcLength, state.steps, 0u,
                                   nextStep, sampleStage(state.offset));
  if (line.steps == 0 && params.keepHistory != 0) emitLinePoint(thread, line);
  return line;
}

// Why the line ends before its next step: its termination code, or running if it does not.
int terminationBeforeStep(LineProgress line) {
  int reason = AMRSTREAM_REASON_RUNNING;
  if (length(line.s.value) < params.terminalSpeed)
    reason = AMRSTREAM_REASON_STAGNATION;
  else if (line.steps == params.maxSteps)
    reason = AMRSTREAM_REASON_MAX_STEPS;
  else if (params.maxTime > 0.0 && abs(line.time) >= params.maxTime)
    reason = AMRSTREAM_REASON_MAX_TIME;
  return reason;
}

// Whether the line pauses before its next step, still running: the round's steps are taken (the
// next round goes on from here), or the line left the pause box (it is handed on).
bool pausesBeforeStep(LineProgress line, uint taken) {
  return taken == params.roundSteps ||
         (taken > 0 && params.pauseOutside != 0u && outsidePauseBox(line.x));
}

// The step to try from the line's point.
struct StepPlan {
  float h;             // the step
  float scale;         // the factor of the stage vectors: the line's direction, or less (below)
  bool endsOnMaxTime;  // whether the step is shortened to end on --max-time
};

// The last step before --max-time is shortened to end on it: the fixed-step integrators
// scale their stage vectors, rk45 starts from the shortened step.
StepPlan planStep(LineProgress line, float sign) {
  precise float h = kIntegrator == AMRSTREAM_INTEGRATOR_RK45 && line.nextStep > 0.0
                        ? line.nextStep
                        : params.stepSize;
  precise const float advance = parameterStep(line.s, h);
  precise float scale = sign;
  // `precise`: the sum that decides it rounds as the CPU's does.
  precise const bool endsOnMaxTime =
      params.maxTime > 0.0 && abs(line.time) + advance > params.maxTime;
  if (endsOnMaxTime) {
    precise const float remaining = (params.maxTime - abs(line.time)) / advance;
    if (kIntegrator == AMRSTREAM_INTEGRATOR_RK45)
      h *= remaining;
    else
      scale = sign * remaining;
  }
  return StepPlan(h, scale, endsOnMaxTime);
}

// Classic fourth-order Runge-Kutta as one loop over its samples, so that the sampling code
// (and its traceRayEXT) appears once; the same sums as the written-out form, in its order.
StepOutcome rk4Step(vec3 x, VectorSample s, float h, float scale) {
  StepOutcome result = StepOutcome(AMRSTREAM_REASON_RUNNING, x, s, h, h);
  precise const vec3 k1 = scale * direction(s, h);
  precise vec3 sum = k1;
  precise vec3 k = k1;
  [[dont_unroll]] for (int stage = 0; stage < 4; ++stage) {
    precise vec3 point;
    if (stage < 3)
      point = x + (stage == 2 ? 1.0 : 0.5) * k;
    else
      point = x + sum / 6.0;
    const VectorSample sampled = samplePoint(point, stage == 3);
    if ((result.reason = sampleFailure(sampled)) != AMRSTREAM_REASON_RUNNING) break;
    if (stage < 3) {
      k = scale * direction(sampled, h);
      sum = sum + (stage == 2 ? 1.0 : 2.0) * k;
    } else {
      result.unwrapped = point;
      result.next = sampled;
    }
  }
  return result;
}

// One step of the kernel's integrator from x (rk4 written out is in advanceLine).
StepOutcome integratorStep(vec3 x, VectorSample s, StepPlan plan) {
  if (kIntegrator == AMRSTREAM_INTEGRATOR_RK4) return rk4Step(x, s, plan.h, plan.scale);
  return kIntegrator == AMRSTREAM_INTEGRATOR_EULER ? eulerStep(x, s, plan.h, plan.scale)
         : kIntegrator == AMRSTREAM_INTEGRATOR_RK2 ? rk2Step(x, s, plan.h, plan.scale)
                                                  : dormandPrinceStep(x, s, plan.h, plan.scale);
}

// --max-length: whether the step keeps the line within it, its length then added to the line's.
bool withinMaxLength(inout LineProgress line, vec3 unwrapped) {
  bool within = true;
  if (params.maxLength > 0.0) {
    precise const float stepLength = length(params.spacing * (unwrapped - line.x));
    precise const float traceLength = line.traceLength + stepLength;
    within = !(traceLength > params.maxLength);
    if (within) line.traceLength = traceLength;
  }
  return within;
}

// Moves the line to the step's end point, with its time advanced by the step taken (or set on
// --max-time), and the end point's whole cells moved into the anchor with deep positions.
void moveToStepEnd(inout LineProgress line, StepOutcome step, bool endsOnMaxTime, float sign) {
  precise const float time = endsOnMaxTime ? sign * params.maxTime
                                           : line.time + sign * parameterStep(line.s, step.step);
  line.time = time;
  if (kDeepPositions) {
    lineAnchor = wrapPeriodic(lineAnchor, step.unwrapped);
    const vec3 whole = floor(step.unwrapped);
    lineAnchor += ivec3(whole);
    precise const vec3 x = step.unwrapped - whole;
    line.x = x;
  } else {
    line.x = wrapCellUnits(step.unwrapped);
  }
  line.s = step.next;
  ++line.steps;
}

void advanceLine(uint thread) {
  const LineState state = statesIn[thread];
  const float sign = state.direction;
  LineProgress line = resumeLine(thread, state);
  int reason = sampleFailure(line.s);
  for (uint taken = 0; reason == AMRSTREAM_REASON_RUNNING; ++taken) {
    if ((reason = terminationBeforeStep(line)) != AMRSTREAM_REASON_RUNNING) break;
    if (pausesBeforeStep(line, taken)) break;
    StepPlan plan = planStep(line, sign);
    StepOutcome step;
    if (kIntegrator == AMRSTREAM_INTEGRATOR_RK4 && !kRk4SampleLoop) {
      // Classic fourth-order Runge-Kutta, the paper's: written out here, as the hot path. As a
      // step function like the others it costs the compute kernels speed
      // (docs/performance-notes.md, "Integrators beside rk4").
      const vec3 x = line.x;
      const float h = plan.h, scale = plan.scale;
      precise const vec3 k1 = scale * direction(line.s, h);
      precise const vec3 p2 = x + 0.5 * k1;
      const VectorSample s2 = sampleStage(p2);
      if ((reason = sampleFailure(s2)) != AMRSTREAM_REASON_RUNNING) break;
      precise const vec3 k2 = scale * direction(s2, h);
      precise const vec3 p3 = x + 0.5 * k2;
      const VectorSample s3 = sampleStage(p3);
      if ((reason = sampleFailure(s3)) != AMRSTREAM_REASON_RUNNING) break;
      precise const vec3 k3 = scale * direction(s3, h);
      precise const vec3 p4 = x + k3;
      const VectorSample s4 = sampleStage(p4);
      if ((reason = sampleFailure(s4)) != AMRSTREAM_REASON_RUNNING) break;
      precise const vec3 k4 = scale * direction(s4, h);
      precise const vec3 unwrapped = x + (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
      const VectorSample sNext = sampleEnd(unwrapped);
      if ((reason = sampleFailure(sNext)) != AMRSTREAM_REASON_RUNNING) break;
      step = StepOutcome(reason, unwrapped, sNext, h, h);
    } else {
      step = integratorStep(line.x, line.s, plan);
      if ((reason = step.reason) != AMRSTREAM_REASON_RUNNING) break;
    }
    if (kIntegrator != AMRSTREAM_INTEGRATOR_RK4) {  // rk4 takes h whole and keeps no next step
      line.nextStep = step.nextStep;
      plan.endsOnMaxTime = plan.endsOnMaxTime && step.step == plan.h;
    }
    if (!withinMaxLength(line, step.unwrapped)) {
      reason = AMRSTREAM_REASON_MAX_LENGTH;
      break;
    }
    moveToStepEnd(line, step, plan.endsOnMaxTime, sign);
    if (params.keepHistory != 0) emitLinePoint(thread, line);
  }
  if (params.keepHistory == 0 && reason != AMRSTREAM_REASON_RUNNING)
    emitLinePoint(thread, line);  // endpoints only: the last point, written once
  statesOut[thread] = LineState(line.x, line.time, line.traceLength, line.steps, state.line, sign,
                                line.nextStep, lineAnchor);
  lineRounds[thread] = LineRound(state.line, line.emitted, line.steps, reason);
}

// 2^params.laneShift invocations a line, the first of them tracing it: rounds of few lines
// spread them over the subgroups, so that a line's loads wait for no other line's.
void advanceLineOfInvocation(uint invocation) {
  const uint line = invocation >> params.laneShift;
  const uint others = invocation & ((1u << params.laneShift) - 1u);
  if (others == 0u && line < params.lineCount) advanceLine(line);
}
