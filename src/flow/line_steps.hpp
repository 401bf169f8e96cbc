#pragma once
// One integration step of a line, per integrator: the CPU twins of the GLSL steps in
// shaders/glsl/include/{euler,rk2,rk4,rk45}_step.glsl, which the GPU tests compare with them.
// Positions are CellPoints (wrapped on periodic axes before sampling); a stage vector k is the
// displacement in finest cells the step would make with that stage's velocity (line_tracer.cpp),
// added to the offset. A step's end point is sampled with `sampleEnd`, which samples it where the
// next step starts (normalized(), with deep positions).

#include <functional>
#include <glm/glm.hpp>

#include "../../shaders/glsl/shared/trace_params.h"
#include "sampler.hpp"

namespace amrstream::flow {

// Samples the vector at a point that may lie outside the domain on a periodic axis.
using StageSampler = std::function<VectorSample(const CellPoint& unwrapped)>;
// The stage vector for sample s and step h (the step mode's units), direction included.
using StageVector = std::function<glm::vec3(const VectorSample& s, float h)>;

struct StepOutcome {
  int reason = 0;         // AMRSTREAM_REASON_RUNNING when the step was taken
  CellPoint unwrapped;    // x plus the step's displacement
  VectorSample next;      // the sample at the wrapped end point
  float step = 0.0f;      // the step taken (rk45: the accepted one)
  float nextStep = 0.0f;  // rk45: the step to try next
};

// Euler, RK2 (midpoint) and RK4 with the fixed step h.
StepOutcome fixedStep(int integrator, const CellPoint& x, const VectorSample& s, float h,
                      const StageSampler& sample, const StageSampler& sampleEnd,
                      const StageVector& stage);

// Dormand-Prince 5(4) from h, shrinking until the error estimate is within the tolerance and the
// displacement within one of the start region's finest cells (or h reaches params.minStep).
StepOutcome dormandPrinceStep(const shared::TraceParams& params, const CellPoint& x,
                              const VectorSample& s, float h, const StageSampler& sample,
                              const StageSampler& sampleEnd, const StageVector& stage);

// 0.9 (ratio)^(1/5) for ratio = limitSquared / errorSquared, and 0.9 (ratio)^(1/2) for the
// displacement, from the two squares' binary exponents alone (exact on every device): the
// factor by which rk45 scales its step, within [0.2, 5].
float stepFactor(float errorSquared, float limitSquared, float displacementSquared,
                 float capSquared);

}  // namespace amrstream::flow
