// RK4 streamline integration with the step mode's direction scaling and VTK termination codes;
// twin of src/flow/integrator.cpp (traceSeed). Needs sampler.glsl.

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

// Outputs are point-major: point k of seed s is at slot k * seedCount + s, so the invocations of
// a subgroup write one step's points to neighbouring slots. The host reorders them.
uint outputSlot(uint seedIndex, uint point) { return point * params.seedCount + seedIndex; }

void traceSeed(uint seedIndex) {
  precise vec3 x = seeds[seedIndex];
  VectorSample s = sampleVector(x);
  precise float time = 0.0, traceLength = 0.0;
  uint points = 1;
  if (params.keepHistory != 0) {
    positions[seedIndex] = x;
    times[seedIndex] = time;
    vectors[seedIndex] = s.value;
  }

  int reason = sampleFailure(s);
  for (uint step = 0; reason == AMRSTREAM_REASON_RUNNING; ++step) {
    if (length(s.value) < params.terminalSpeed) {
      reason = AMRSTREAM_REASON_STAGNATION;
      break;
    }
    if (step == params.maxSteps) {
      reason = AMRSTREAM_REASON_MAX_STEPS;
      break;
    }
    precise const vec3 k1 = direction(s);
    precise const vec3 p2 = x + 0.5 * k1;
    const VectorSample s2 = sampleVector(p2);
    if ((reason = sampleFailure(s2)) != AMRSTREAM_REASON_RUNNING) break;
    precise const vec3 k2 = direction(s2);
    precise const vec3 p3 = x + 0.5 * k2;
    const VectorSample s3 = sampleVector(p3);
    if ((reason = sampleFailure(s3)) != AMRSTREAM_REASON_RUNNING) break;
    precise const vec3 k3 = direction(s3);
    precise const vec3 p4 = x + k3;
    const VectorSample s4 = sampleVector(p4);
    if ((reason = sampleFailure(s4)) != AMRSTREAM_REASON_RUNNING) break;
    precise const vec3 k4 = direction(s4);
    precise const vec3 next = x + (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
    const VectorSample sNext = sampleVector(next);
    if ((reason = sampleFailure(sNext)) != AMRSTREAM_REASON_RUNNING) break;

    if (params.maxLength > 0.0) {
      precise const float stepLength = length(params.spacing * (next - x));
      if (traceLength + stepLength > params.maxLength) {
        reason = AMRSTREAM_REASON_MAX_LENGTH;
        break;
      }
      traceLength += stepLength;
    }
    time += parameterStep(s);
    x = next;
    s = sNext;
    if (params.keepHistory != 0) {
      const uint slot = outputSlot(seedIndex, points);
      positions[slot] = x;
      times[slot] = time;
      vectors[slot] = s.value;
    }
    ++points;
  }
  if (params.keepHistory == 0) {  // only the last point, written once
    positions[seedIndex] = x;
    times[seedIndex] = time;
    vectors[seedIndex] = s.value;
  }
  pointCounts[seedIndex] = points;  // points taken; the host derives how many are stored
  reasons[seedIndex] = reason;
}
