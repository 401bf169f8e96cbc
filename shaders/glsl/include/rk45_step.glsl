// Dormand-Prince 5(4) from step h, shrinking until the error estimate is within the tolerance
// and the displacement within one of the start region's finest cells (or h reaches
// params.minStep); twin of dormandPrinceStep() in src/flow/line_steps.cpp, with the tableau of
// shared/dormand_prince.h.

#include "../shared/dormand_prince.h"

// The binary exponent of a positive normal float; smaller values count as the smallest normal.
int binaryExponent(float value) {
  return int((floatBitsToUint(max(value, 1.17549435e-38)) >> 23) & 0xffu);
}

const float kHalfTenths[10] = float[10](AMRSTREAM_HALF_TENTHS);

// 2^(-d/10) for an integer d.
float halfToTheTenths(int d) {
  const int whole = d >= 0 ? d / 10 : -((9 - d) / 10);  // floor(d / 10)
  return ldexp(kHalfTenths[d - 10 * whole], -whole);
}

float stepFactor(float errorSquared, float limitSquared, float displacementSquared,
                 float capSquared) {
  const int dError = binaryExponent(errorSquared) - binaryExponent(limitSquared);
  const int dDisplacement =
      binaryExponent(displacementSquared * AMRSTREAM_RK45_BINADE_SHIFT) - binaryExponent(capSquared);
  precise const float factor =
      0.9 * min(halfToTheTenths(dError), halfToTheTenths(5 * dDisplacement));
  return clamp(factor, 0.2, 5.0);
}

StepOutcome dormandPrinceStep(vec3 x, VectorSample s, float h0, float scale) {
  StepOutcome result = StepOutcome(AMRSTREAM_REASON_RUNNING, x, s, h0, h0);
  precise float h = h0;
  const float width = s.cellWidth;
  precise const float capSquared = width * width;
  precise const float limitSquared = params.toleranceSquared * capSquared;
  for (int attempt = 0;; ++attempt) {
    precise const vec3 k1 = scale * direction(s, h);
    precise const vec3 p2 = x + AMRSTREAM_DP_A21 * k1;
    const VectorSample s2 = sampleStage(p2);
    if ((result.reason = sampleFailure(s2)) != AMRSTREAM_REASON_RUNNING) return result;
    precise const vec3 k2 = scale * direction(s2, h);
    precise const vec3 p3 = x + (AMRSTREAM_DP_A31 * k1 + AMRSTREAM_DP_A32 * k2);
    const VectorSample s3 = sampleStage(p3);
    if ((result.reason = sampleFailure(s3)) != AMRSTREAM_REASON_RUNNING) return result;
    precise const vec3 k3 = scale * direction(s3, h);
    precise const vec3 p4 =
        x + (AMRSTREAM_DP_A41 * k1 + AMRSTREAM_DP_A42 * k2 + AMRSTREAM_DP_A43 * k3);
    const VectorSample s4 = sampleStage(p4);
    if ((result.reason = sampleFailure(s4)) != AMRSTREAM_REASON_RUNNING) return result;
    precise const vec3 k4 = scale * direction(s4, h);
    precise const vec3 p5 = x + (AMRSTREAM_DP_A51 * k1 + AMRSTREAM_DP_A52 * k2 +
                                 AMRSTREAM_DP_A53 * k3 + AMRSTREAM_DP_A54 * k4);
    const VectorSample s5 = sampleStage(p5);
    if ((result.reason = sampleFailure(s5)) != AMRSTREAM_REASON_RUNNING) return result;
    precise const vec3 k5 = scale * direction(s5, h);
    precise const vec3 p6 = x + (AMRSTREAM_DP_A61 * k1 + AMRSTREAM_DP_A62 * k2 +
                                 AMRSTREAM_DP_A63 * k3 + AMRSTREAM_DP_A64 * k4 +
                                 AMRSTREAM_DP_A65 * k5);
    const VectorSample s6 = sampleStage(p6);
    if ((result.reason = sampleFailure(s6)) != AMRSTREAM_REASON_RUNNING) return result;
    precise const vec3 k6 = scale * direction(s6, h);
    precise const vec3 displacement = AMRSTREAM_DP_B1 * k1 + AMRSTREAM_DP_B3 * k3 +
                                      AMRSTREAM_DP_B4 * k4 + AMRSTREAM_DP_B5 * k5 +
                                      AMRSTREAM_DP_B6 * k6;
    precise const vec3 unwrapped = x + displacement;
    const VectorSample end = sampleEnd(unwrapped);
    if ((result.reason = sampleFailure(end)) != AMRSTREAM_REASON_RUNNING) return result;
    precise const vec3 k7 = scale * direction(end, h);
    precise const vec3 error = AMRSTREAM_DP_E1 * k1 + AMRSTREAM_DP_E3 * k3 +
                               AMRSTREAM_DP_E4 * k4 + AMRSTREAM_DP_E5 * k5 +
                               AMRSTREAM_DP_E6 * k6 + AMRSTREAM_DP_E7 * k7;
    precise const float errorSquared = error.x * error.x + error.y * error.y + error.z * error.z;
    precise const float displacementSquared = displacement.x * displacement.x +
                                              displacement.y * displacement.y +
                                              displacement.z * displacement.z;
    const float factor = stepFactor(errorSquared, limitSquared, displacementSquared, capSquared);
    precise const float capWithMargin = capSquared * AMRSTREAM_RK45_CAP_SQUARED_MARGIN;
    const bool accepted = (errorSquared <= limitSquared && displacementSquared <= capWithMargin) ||
                          h <= params.minStep || attempt + 1 == AMRSTREAM_RK45_MAX_ATTEMPTS;
    if (accepted) {
      result.unwrapped = unwrapped;
      result.next = end;
      result.step = h;
      precise const float grown = h * factor;
      result.nextStep = clamp(grown, params.minStep, params.maxStep);
      return result;
    }
    precise const float shrunk = h * min(factor, 0.9);
    h = max(params.minStep, shrunk);
  }
  return result;
}
