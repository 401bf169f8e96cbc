#include "line_steps.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "../../shaders/glsl/shared/dormand_prince.h"
#include "../../shaders/glsl/shared/trace_codes.h"

namespace amrstream::flow {

namespace {

int sampleFailure(const VectorSample& s) {
  if (!s.located) return AMRSTREAM_REASON_OUT_OF_DOMAIN;
  if (!s.valid) return AMRSTREAM_REASON_UNEXPECTED_VALUE;
  return AMRSTREAM_REASON_RUNNING;
}

// The binary exponent of a positive normal float; smaller values count as the smallest normal.
int binaryExponent(float value) {
  const auto bits = std::bit_cast<std::uint32_t>(std::max(value, 1.17549435e-38f));
  return int((bits >> 23) & 0xffu);
}

constexpr float kHalfTenths[10] = {AMRSTREAM_HALF_TENTHS};

// 2^(-d/10) for an integer d, exactly as the GLSL twin computes it.
float halfToTheTenths(int d) {
  const int whole = d >= 0 ? d / 10 : -((9 - d) / 10);  // floor(d / 10)
  return std::ldexp(kHalfTenths[d - 10 * whole], -whole);
}

}  // namespace

float stepFactor(float errorSquared, float limitSquared, float displacementSquared,
                 float capSquared) {
  // err / tol = 2^(dErr / 2), so (tol / err)^(1/5) = 2^(-dErr / 10); likewise the displacement's
  // square root is 2^(-5 dDisp / 10).
  const int dError = binaryExponent(errorSquared) - binaryExponent(limitSquared);
  const int dDisplacement = binaryExponent(displacementSquared * AMRSTREAM_RK45_BINADE_SHIFT) -
                            binaryExponent(capSquared);
  const float byError = halfToTheTenths(dError),
              byDisplacement = halfToTheTenths(5 * dDisplacement);
  return std::clamp(0.9f * std::min(byError, byDisplacement), 0.2f, 5.0f);
}

StepOutcome fixedStep(int integrator, const CellPoint& x, const VectorSample& s, float h,
                      const StageSampler& sample, const StageSampler& sampleEnd,
                      const StageVector& stage) {
  StepOutcome out;
  out.step = out.nextStep = h;
  const glm::vec3 k1 = stage(s, h);
  if (integrator == AMRSTREAM_INTEGRATOR_EULER) {
    out.unwrapped = moved(x, k1);
  } else if (integrator == AMRSTREAM_INTEGRATOR_RK2) {
    const VectorSample s2 = sample(moved(x, 0.5f * k1));
    if ((out.reason = sampleFailure(s2))) return out;
    out.unwrapped = moved(x, stage(s2, h));
  } else {
    const VectorSample s2 = sample(moved(x, 0.5f * k1));
    if ((out.reason = sampleFailure(s2))) return out;
    const glm::vec3 k2 = stage(s2, h);
    const VectorSample s3 = sample(moved(x, 0.5f * k2));
    if ((out.reason = sampleFailure(s3))) return out;
    const glm::vec3 k3 = stage(s3, h);
    const VectorSample s4 = sample(moved(x, k3));
    if ((out.reason = sampleFailure(s4))) return out;
    const glm::vec3 k4 = stage(s4, h);
    out.unwrapped = moved(x, (k1 + 2.0f * k2 + 2.0f * k3 + k4) / 6.0f);
  }
  out.next = sampleEnd(out.unwrapped);
  out.reason = sampleFailure(out.next);
  return out;
}

StepOutcome dormandPrinceStep(const shared::TraceParams& params, const CellPoint& x,
                              const VectorSample& s, float h, const StageSampler& sample,
                              const StageSampler& sampleEnd, const StageVector& stage) {
  // Dormand and Prince (1980): the fifth-order solution is propagated, the fourth-order one only
  // estimates the error; the last stage is the sample at the end point (first same as last).
  StepOutcome out;
  const float width = s.cellWidth;  // the cap and the tolerance are in these cell widths
  const float capSquared = width * width;
  const float limitSquared = params.toleranceSquared * capSquared;
  for (int attempt = 0;; ++attempt) {
    const glm::vec3 k1 = stage(s, h);
    const VectorSample s2 = sample(moved(x, AMRSTREAM_DP_A21 * k1));
    if ((out.reason = sampleFailure(s2))) return out;
    const glm::vec3 k2 = stage(s2, h);
    const VectorSample s3 = sample(moved(x, (AMRSTREAM_DP_A31 * k1 + AMRSTREAM_DP_A32 * k2)));
    if ((out.reason = sampleFailure(s3))) return out;
    const glm::vec3 k3 = stage(s3, h);
    const VectorSample s4 =
        sample(moved(x, (AMRSTREAM_DP_A41 * k1 + AMRSTREAM_DP_A42 * k2 + AMRSTREAM_DP_A43 * k3)));
    if ((out.reason = sampleFailure(s4))) return out;
    const glm::vec3 k4 = stage(s4, h);
    const VectorSample s5 = sample(moved(x, (AMRSTREAM_DP_A51 * k1 + AMRSTREAM_DP_A52 * k2 +
                                             AMRSTREAM_DP_A53 * k3 + AMRSTREAM_DP_A54 * k4)));
    if ((out.reason = sampleFailure(s5))) return out;
    const glm::vec3 k5 = stage(s5, h);
    const VectorSample s6 =
        sample(moved(x, (AMRSTREAM_DP_A61 * k1 + AMRSTREAM_DP_A62 * k2 + AMRSTREAM_DP_A63 * k3 +
                         AMRSTREAM_DP_A64 * k4 + AMRSTREAM_DP_A65 * k5)));
    if ((out.reason = sampleFailure(s6))) return out;
    const glm::vec3 k6 = stage(s6, h);
    const glm::vec3 displacement = AMRSTREAM_DP_B1 * k1 + AMRSTREAM_DP_B3 * k3 +
                                   AMRSTREAM_DP_B4 * k4 + AMRSTREAM_DP_B5 * k5 +
                                   AMRSTREAM_DP_B6 * k6;
    const VectorSample end = sampleEnd(moved(x, displacement));
    if ((out.reason = sampleFailure(end))) return out;
    const glm::vec3 k7 = stage(end, h);
    const glm::vec3 error = AMRSTREAM_DP_E1 * k1 + AMRSTREAM_DP_E3 * k3 + AMRSTREAM_DP_E4 * k4 +
                            AMRSTREAM_DP_E5 * k5 + AMRSTREAM_DP_E6 * k6 + AMRSTREAM_DP_E7 * k7;
    const float errorSquared = error.x * error.x + error.y * error.y + error.z * error.z;
    const float displacementSquared = displacement.x * displacement.x +
                                      displacement.y * displacement.y +
                                      displacement.z * displacement.z;
    const float factor = stepFactor(errorSquared, limitSquared, displacementSquared, capSquared);
    const bool accepted = (errorSquared <= limitSquared &&
                           displacementSquared <= capSquared * AMRSTREAM_RK45_CAP_SQUARED_MARGIN) ||
                          h <= params.minStep || attempt + 1 == AMRSTREAM_RK45_MAX_ATTEMPTS;
    if (accepted) {
      out.unwrapped = moved(x, displacement);
      out.next = end;
      out.step = h;
      out.nextStep = std::clamp(h * factor, params.minStep, params.maxStep);
      return out;
    }
    h = std::max(params.minStep, h * std::min(factor, 0.9f));
  }
}

}  // namespace amrstream::flow
