// Euler, RK2 and the adaptive RK45 against analytic answers: convergence orders, the error
// control's tolerance, fewer steps than RK4 at equal error, and steps that adapt to the field.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "flow/cpu_tracer.hpp"
#include "flow/line_steps.hpp"
#include "flow_test_support.hpp"

namespace amrstream::flow {
namespace {

// One level of 16 x 16 x 8 unit cells: the tent reconstruction of a linear field is exact there,
// so only the integrator and float rounding remain.
constexpr glm::dvec3 kCentre(8.0, 8.0, 4.0);

VectorVolume linearFieldVolume(const testing::VectorFunction& f) {
  testing::RandomAmrOptions layout;
  layout.levels = 1;
  layout.rootCells = glm::ivec3(16, 16, 8);
  return testing::volumeOf(testing::randomAmr(0, layout, f));
}

// Solid-body rotation about the z axis through kCentre, one revolution per 100 time units.
constexpr double kOmega = 2.0 * std::numbers::pi / 100.0;  // T = 100
const VectorVolume& rotation() {
  static const VectorVolume volume = linearFieldVolume([](glm::dvec3 p) {
    return glm::vec3(-kOmega * (p.y - kCentre.y), kOmega * (p.x - kCentre.x), 0.0);
  });
  return volume;
}
glm::dvec3 rotated(glm::dvec3 seed, double t) {
  const glm::dvec3 r = seed - kCentre;
  const double c = std::cos(kOmega * t), s = std::sin(kOmega * t);
  return kCentre + glm::dvec3(c * r.x - s * r.y, s * r.x + c * r.y, r.z);
}

// v = lambda (p - c): x(t) = c + (x0 - c) e^(lambda t).
constexpr double kLambda = 0.05;
const VectorVolume& expansion() {
  static const VectorVolume volume =
      linearFieldVolume([](glm::dvec3 p) { return glm::vec3(kLambda * (p - kCentre)); });
  return volume;
}

struct Run {
  glm::dvec3 end;
  std::uint32_t steps;
  float time;
};

// Forward from the seed in time mode until |IntegrationTime| reaches maxTime.
Run traceFor(const VectorVolume& volume, glm::dvec3 seed, Integrator integrator, float step,
             float maxTime, float tolerance = 1e-4f) {
  TraceOptions options;
  options.stepMode = StepMode::Time;
  options.integrator = integrator;
  options.stepSize = step;
  options.tolerance = tolerance;
  options.minStep = step / 100.0f;
  options.maxStep = step * 100.0f;
  options.maxTime = maxTime;
  options.maxSteps = 1000000;
  options.direction = Direction::Forward;
  const glm::dvec3 seeds[] = {seed};
  const TraceSet t = traceStreamlines(volume, seeds, options);
  EXPECT_EQ(t.reasons[0], AMRSTREAM_REASON_MAX_TIME);
  return {glm::dvec3(t.positions.back()), t.steps[0], t.times.back()};
}

double orderOfConvergence(Integrator integrator, float coarseStep) {
  const glm::dvec3 seed = kCentre + glm::dvec3(3.0, 0.0, 0.0);
  const double T = 25.0;
  const auto error = [&](float h) {
    return glm::length(traceFor(rotation(), seed, integrator, h, float(T)).end - rotated(seed, T));
  };
  const double coarse = error(coarseStep), fine = error(coarseStep / 2.0f);
  std::printf("h %g: error %.3g cells, h/2: %.3g, order %.3f\n", coarseStep, coarse, fine,
              std::log2(coarse / fine));
  return std::log2(coarse / fine);
}

TEST(Integrators, EulerConvergesAtFirstOrder) {
  const double order = orderOfConvergence(Integrator::Euler, 0.25f);
  EXPECT_GT(order, 0.9);
  EXPECT_LT(order, 1.1);
}

TEST(Integrators, Rk2ConvergesAtSecondOrder) {
  const double order = orderOfConvergence(Integrator::Rk2, 1.0f);
  EXPECT_GT(order, 1.8);
  EXPECT_LT(order, 2.2);
}

// The smallest number of fixed RK4 steps over [0, T] whose error is at most `target`.
std::uint32_t rk4StepsForError(const VectorVolume& volume, glm::dvec3 seed, double T,
                               glm::dvec3 exact, double target) {
  for (std::uint32_t n = 4; n < 100000; n = n + n / 8 + 1) {
    const Run run = traceFor(volume, seed, Integrator::Rk4, float(T / n), float(T));
    if (glm::length(run.end - exact) <= target) return run.steps;
  }
  return 100000;
}

// The local error per step is at most tolerance cell widths; summed over the steps (amplified by
// at most `growth`, the field's e^(lambda T) for the expansion) it bounds the global error.
void expectToleranceMetWithFewerStepsThanRk4(const VectorVolume& volume, glm::dvec3 seed, double T,
                                             glm::dvec3 exact, float tolerance, double growth) {
  const Run rk45 = traceFor(volume, seed, Integrator::Rk45, 1.0f, float(T), tolerance);
  EXPECT_EQ(rk45.time, float(T));  // the last step lands on T
  const double error = glm::length(rk45.end - exact);
  EXPECT_LE(error, double(rk45.steps) * tolerance * growth) << rk45.steps << " steps";
  const std::uint32_t rk4Steps = rk4StepsForError(volume, seed, T, exact, error);
  EXPECT_LT(rk45.steps, rk4Steps) << "rk45 error " << error;
  std::printf("tolerance %g: rk45 %u steps, error %.3g cells; rk4 needs %u steps\n", tolerance,
              rk45.steps, error, rk4Steps);
}

TEST(Integrators, Rk45MeetsTheToleranceOnARotationWithFewerStepsThanRk4) {
  const glm::dvec3 seed = kCentre + glm::dvec3(0.0, 2.0, 0.0);
  for (float tolerance : {1e-3f, 1e-4f, 1e-5f})
    expectToleranceMetWithFewerStepsThanRk4(rotation(), seed, 100.0, rotated(seed, 100.0),
                                            tolerance, 1.0);
}

TEST(Integrators, Rk45MeetsTheToleranceOnAnExponentialFieldWithFewerStepsThanRk4) {
  const glm::dvec3 seed = kCentre + glm::dvec3(0.5, -0.4, 0.1);
  const double T = 40.0, growth = std::exp(kLambda * T);
  const glm::dvec3 exact = kCentre + (seed - kCentre) * growth;
  for (float tolerance : {1e-3f, 1e-4f, 1e-5f})
    expectToleranceMetWithFewerStepsThanRk4(expansion(), seed, T, exact, tolerance, growth);
}

TEST(Integrators, Rk45StepsAreSmallWhereTheFieldTurnsFast) {
  // In arc mode a circle of radius r turns by 1/r per cell: the error of a step of h cells grows
  // like h^5 / r^4, so the accepted steps near the centre are several times shorter.
  const auto meanStep = [](double radius) {
    TraceOptions options;
    options.stepMode = StepMode::Arc;
    options.integrator = Integrator::Rk45;
    options.tolerance = 1e-7f;
    options.maxLength = float(2.0 * std::numbers::pi * radius);  // one revolution
    options.maxSteps = 100000;
    options.direction = Direction::Forward;
    const glm::dvec3 seeds[] = {kCentre + glm::dvec3(radius, 0.0, 0.0)};
    const TraceSet t = traceStreamlines(rotation(), seeds, options);
    return options.maxLength / double(t.steps[0]);
  };
  const double nearCentre = meanStep(1.5), far = meanStep(6.0);
  EXPECT_GT(far, 1.5 * nearCentre) << "mean steps " << nearCentre << " and " << far << " cells";
  EXPECT_LE(far, 1.0);  // never more than one cell: the displacement cap
}

TEST(Integrators, StepFactorFollowsTheFifthRootOfTheErrorRatio) {
  // err = tol / 32 -> (32)^(1/5) = 2, times the safety factor 0.9.
  EXPECT_NEAR(stepFactor(1.0f / 1024.0f, 1.0f, 0.0f, 1.0f), 1.8f, 0.1f);
  EXPECT_NEAR(stepFactor(1024.0f, 1.0f, 0.0f, 1.0f), 0.45f, 0.03f);
  EXPECT_EQ(stepFactor(1e20f, 1.0f, 0.0f, 1.0f), 0.2f);  // bounded
  EXPECT_EQ(stepFactor(0.0f, 1.0f, 0.0f, 1.0f), 5.0f);
  EXPECT_NEAR(stepFactor(0.0f, 1.0f, 16.0f, 1.0f), 0.9f / 4.0f, 0.01f);  // displacement 4 cells
}

}  // namespace
}  // namespace amrstream::flow
