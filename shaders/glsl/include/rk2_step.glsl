// The midpoint rule (VTK's vtkRungeKutta2) with the fixed step h; twin of fixedStep() in
// src/flow/line_steps.cpp.
StepOutcome rk2Step(vec3 x, VectorSample s, float h, float scale) {
  StepOutcome result = StepOutcome(AMRSTREAM_REASON_RUNNING, x, s, h, h);
  precise const vec3 k1 = scale * direction(s, h);
  precise const vec3 p2 = x + 0.5 * k1;
  const VectorSample s2 = sampleStage(p2);
  if ((result.reason = sampleFailure(s2)) != AMRSTREAM_REASON_RUNNING) return result;
  precise const vec3 k2 = scale * direction(s2, h);
  precise const vec3 unwrapped = x + k2;
  result.unwrapped = unwrapped;
  result.next = sampleEnd(unwrapped);
  result.reason = sampleFailure(result.next);
  return result;
}
