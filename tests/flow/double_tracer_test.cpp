// The double-precision oracle of tests/support on its own: its reconstruction reproduces what the
// tent basis must, its RK4 follows the spiral's closed form, and it ends traces where samples fail.

#include "double_tracer.hpp"

#include <gtest/gtest.h>

#include <random>

#include "flow_test_support.hpp"
#include "synth/spiral_field.hpp"

namespace amrstream::testing {
namespace {

const std::array<std::string, 3> kVector{"vx", "vy", "vz"};

glm::dvec3 randomPoint(glm::dvec3 lower, glm::dvec3 upper, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  return lower + glm::dvec3(u(rng), u(rng), u(rng)) * (upper - lower);
}

TEST(DoubleTracer, ReconstructsConstantsOnMultiLevelLayouts) {
  std::mt19937_64 rng(5);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    RandomAmrOptions layout;
    layout.levels = 1 + int(seed % 5);
    layout.origin = glm::ivec3(-(1 << (layout.levels - 1)), 0, 0);
    const bricks::AmrField amr =
        randomAmr(seed, layout, [](glm::dvec3) { return glm::vec3(0.25f, -2.0f, 7.0f); });
    const TentField field(amr, kVector);
    for (int k = 0; k < 200; ++k) {
      const TentSample s = field.sample(
          randomPoint(glm::dvec3(amr.bounds().lower), glm::dvec3(amr.bounds().upper), rng));
      ASSERT_EQ(s.status, TentSample::Status::Valid);
      EXPECT_LT(glm::length(s.value - glm::dvec3(0.25, -2.0, 7.0)), 1e-14);
    }
  }
}

// Trilinear on a uniform grid: exact for linear fields where all eight neighbours exist.
TEST(DoubleTracer, ReconstructsLinearFieldsInsideAUniformGrid) {
  const auto linear = [](glm::dvec3 p) { return glm::dvec3(p.x - 2.0 * p.z, 3.0 * p.y, 0.5); };
  const TentField field(uniformGrid(8, [&](glm::dvec3 p) { return glm::vec3(linear(p)); }),
                        kVector);
  std::mt19937_64 rng(6);
  for (int k = 0; k < 200; ++k) {
    const glm::dvec3 p = randomPoint(glm::dvec3(0.5), glm::dvec3(7.5), rng);
    EXPECT_LT(glm::length(field.sample(p).value - linear(p)), 1e-12);
  }
  EXPECT_EQ(field.levelAt(glm::dvec3(3.5)), 0);
  EXPECT_EQ(field.levelAt(glm::dvec3(8.5)), -1);
}

// On a uniform grid the reconstruction of the spiral is exact (up to float storage), so the
// trace departs from the closed form by RK4's error alone.
TEST(DoubleTracer, FollowsTheSpiralsClosedForm) {
  const synth::SpiralField spiral{2.0, 0.2};
  const glm::dvec3 centre(16.3, 15.8, 16.1);
  const DoubleTracer tracer(
      uniformGrid(32, [&](glm::dvec3 p) { return glm::vec3(spiral.velocity(p - centre)); }),
      kVector);
  const glm::dvec3 seed = centre + glm::dvec3(5.0, 1.0, 0.5);
  const double h = 1.0 / 64;
  const DoubleTrace trace = tracer.trace(seed, h, 300);
  ASSERT_EQ(trace.end, DoubleTraceEnd::StepsDone);
  ASSERT_EQ(trace.steps(), 300u);
  double worst = 0.0;
  for (std::size_t n = 0; n < trace.positions.size(); ++n)
    worst = std::max(worst, glm::length(trace.positions[n] - centre -
                                        spiral.offsetAfter(seed - centre, double(n) * h)));
  // RK4's own error: 300 local errors of (h |lambda|)^5 / 120 with h |lambda| ~ 1/32, relative to
  // offsets up to 13 cells, about 1e-6 cells (measured 1.1e-6); float storage adds less.
  EXPECT_LT(worst, 1e-5);
}

TEST(DoubleTracer, EndsOutsideTheDomainAndWhereNoCellWeighs) {
  const DoubleTracer tracer(twoBlocksWithAGap(), kVector);  // v = (1, 1, 1)
  const DoubleTrace outside = tracer.trace(glm::dvec3(-0.5, 1.0, 1.0), 0.1, 10);
  EXPECT_EQ(outside.end, DoubleTraceEnd::OutOfDomain);
  EXPECT_EQ(outside.steps(), 0u);

  // Steps of 0.125 along (1, 1, 1) from x = 3.5: the step from x = 4.375 would sample x = 4.5,
  // where every weight vanishes (the gap), so it is not taken.
  const DoubleTrace intoTheGap = tracer.trace(glm::dvec3(3.5, 0.25, 0.25), 0.125, 20);
  EXPECT_EQ(intoTheGap.end, DoubleTraceEnd::InvalidSample);
  EXPECT_EQ(intoTheGap.steps(), 7u);
  EXPECT_EQ(intoTheGap.positions.back(), glm::dvec3(4.375, 1.125, 1.125));

  const DoubleTrace throughTheTop = tracer.trace(glm::dvec3(1.0, 1.0, 3.0), 0.25, 20);
  EXPECT_EQ(throughTheTop.end, DoubleTraceEnd::OutOfDomain);
  EXPECT_EQ(throughTheTop.steps(), 3u);  // z = 3.75; the next step would reach z = 4
}

}  // namespace
}  // namespace amrstream::testing
