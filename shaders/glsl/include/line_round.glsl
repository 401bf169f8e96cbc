// One tracing round of one line: at most params.roundSteps RK4 steps with the step mode's
// direction scaling, VTK termination codes, periodic wrapping and the --max-time shortening of
// the last step; twin of src/flow/line_tracer.cpp (advanceLine). Needs sampler.glsl.

// `precise` throughout, as in sampler.glsl: no FMA contraction, like the CPU reference.
float parameterStep(VectorSample s) {
  precise const float step = params.stepMode == AMRSTREAM_STEP_TIME
                                 ? params.stepSize
                                 : params.stepSize * s.cellWidth * params.physicalCellWidth;
  return step;
}

vec3 direction(VectorSample s) {
  precise vec3 v = s.value;
  if (params.stepMode == AMRSTREAM_STEP_ARC) {
    precise const float speed = length(v);
    v = speed > 0.0 ? v / speed : vec3(0.0);
  }
  precise const vec3 k = parameterStep(s) * v * params.cellsPerPhysical;
  return k;
}

int sampleFailure(VectorSample s) {
  if (!s.located) return AMRSTREAM_REASON_OUT_OF_DOMAIN;
  if (!s.valid) return AMRSTREAM_REASON_UNEXPECTED_VALUE;
  return AMRSTREAM_REASON_RUNNING;
}

// Outputs are point-major: point k of thread t is at slot k * lineCount + t, so the invocations
// of a subgroup write one step's points to neighbouring slots. The compaction kernels gather them.
void emitPoint(uint thread, uint k, vec3 x, float time, VectorSample s) {
  const uint slot = k * params.lineCount + thread;
  outPositions[slot] = x;
  outTimes[slot] = time;
  outVectors[slot] = s.value;
  outRegions[slot] = s.region;
}

void advanceLine(uint thread) {
  const LineState state = statesIn[thread];
  const float sign = state.direction;
  precise vec3 x = state.position;
  precise float time = state.time, traceLength = state.arcLength;
  uint steps = state.steps, emitted = 0;
  VectorSample s = sampleVector(wrapPeriodic(x));
  if (steps == 0 && params.keepHistory != 0) emitPoint(thread, emitted++, x, time, s);

  int reason = sampleFailure(s);
  for (uint taken = 0; reason == AMRSTREAM_REASON_RUNNING; ++taken) {
    if (length(s.value) < params.terminalSpeed) {
      reason = AMRSTREAM_REASON_STAGNATION;
      break;
    }
    if (steps == params.maxSteps) {
      reason = AMRSTREAM_REASON_MAX_STEPS;
      break;
    }
    if (params.maxTime > 0.0 && abs(time) >= params.maxTime) {
      reason = AMRSTREAM_REASON_MAX_TIME;
      break;
    }
    if (taken == params.roundSteps) break;  // paused; the next round goes on from here

    // The last step before --max-time is shortened to end on it.
    precise const float advance = parameterStep(s);
    precise float scale = sign;
    const bool endsOnMaxTime = params.maxTime > 0.0 && abs(time) + advance > params.maxTime;
    if (endsOnMaxTime) scale = sign * ((params.maxTime - abs(time)) / advance);

    precise const vec3 k1 = scale * direction(s);
    precise const vec3 p2 = x + 0.5 * k1;
    const VectorSample s2 = sampleVector(wrapPeriodic(p2));
    if ((reason = sampleFailure(s2)) != AMRSTREAM_REASON_RUNNING) break;
    precise const vec3 k2 = scale * direction(s2);
    precise const vec3 p3 = x + 0.5 * k2;
    const VectorSample s3 = sampleVector(wrapPeriodic(p3));
    if ((reason = sampleFailure(s3)) != AMRSTREAM_REASON_RUNNING) break;
    precise const vec3 k3 = scale * direction(s3);
    precise const vec3 p4 = x + k3;
    const VectorSample s4 = sampleVector(wrapPeriodic(p4));
    if ((reason = sampleFailure(s4)) != AMRSTREAM_REASON_RUNNING) break;
    precise const vec3 k4 = scale * direction(s4);
    precise const vec3 unwrapped = x + (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
    precise const vec3 next = wrapPeriodic(unwrapped);
    const VectorSample sNext = sampleVector(next);
    if ((reason = sampleFailure(sNext)) != AMRSTREAM_REASON_RUNNING) break;

    if (params.maxLength > 0.0) {
      precise const float stepLength = length(params.spacing * (unwrapped - x));
      if (traceLength + stepLength > params.maxLength) {
        reason = AMRSTREAM_REASON_MAX_LENGTH;
        break;
      }
      traceLength += stepLength;
    }
    time = endsOnMaxTime ? sign * params.maxTime : time + sign * advance;
    x = next;
    s = sNext;
    ++steps;
    if (params.keepHistory != 0) emitPoint(thread, emitted++, x, time, s);
  }
  if (params.keepHistory == 0 && reason != AMRSTREAM_REASON_RUNNING)
    emitPoint(thread, emitted++, x, time, s);  // endpoints only: the last point, written once
  statesOut[thread] = LineState(x, time, traceLength, steps, state.line, sign);
  lineRounds[thread] = LineRound(state.line, emitted, steps, reason);
}
