// Forward Euler with the fixed step h; twin of fixedStep() in src/flow/line_steps.cpp.
StepOutcome eulerStep(vec3 x, VectorSample s, float h, float scale) {
  precise const vec3 k1 = scale * direction(s, h);
  precise const vec3 unwrapped = x + k1;
  const VectorSample next = sampleEnd(unwrapped);
  return StepOutcome(sampleFailure(next), unwrapped, next, h, h);
}
