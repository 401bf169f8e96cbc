// Classic fourth-order Runge-Kutta with the fixed step h (the paper's integrator); twin of
// fixedStep() in src/flow/line_steps.cpp.
StepOutcome rk4Step(vec3 x, VectorSample s, float h, float scale) {
  StepOutcome result = StepOutcome(AMRSTREAM_REASON_RUNNING, x, s, h, h);
  precise const vec3 k1 = scale * direction(s, h);
  precise const vec3 p2 = x + 0.5 * k1;
  const VectorSample s2 = sampleStage(p2);
  if ((result.reason = sampleFailure(s2)) != AMRSTREAM_REASON_RUNNING) return result;
  precise const vec3 k2 = scale * direction(s2, h);
  precise const vec3 p3 = x + 0.5 * k2;
  const VectorSample s3 = sampleStage(p3);
  if ((result.reason = sampleFailure(s3)) != AMRSTREAM_REASON_RUNNING) return result;
  precise const vec3 k3 = scale * direction(s3, h);
  precise const vec3 p4 = x + k3;
  const VectorSample s4 = sampleStage(p4);
  if ((result.reason = sampleFailure(s4)) != AMRSTREAM_REASON_RUNNING) return result;
  precise const vec3 k4 = scale * direction(s4, h);
  precise const vec3 unwrapped = x + (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
  result.unwrapped = unwrapped;
  result.next = sampleStage(unwrapped);
  result.reason = sampleFailure(result.next);
  return result;
}
