// Periodic domains: the sampler against the brute-force tent sum with periodic distances, and
// traces through the ABC flow on its periodic box against the analytic streamline.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "flow/cpu_tracer.hpp"
#include "flow/sampler.hpp"
#include "flow_test_support.hpp"
#include "synth/abc_field.hpp"
#include "synth/generators.hpp"
#include "volume_options.hpp"

namespace amrstream::flow {
namespace {

// B(p) = sum_i H_i(p) v_i / sum_i H_i(p) with the distance to each cell centre taken to its
// nearest periodic image along the periodic axes, in double precision.
glm::dvec3 periodicBruteForce(const bricks::AmrField& field, const PeriodicAxes& periodic,
                              glm::dvec3 p) {
  const CellBox box = field.bounds();
  const glm::dvec3 period(box.upper - box.lower);
  glm::dvec3 sum(0.0);
  double weightSum = 0.0;
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const double w = bricks::AmrField::cellWidth(field.levels()[i]);
    glm::dvec3 d = glm::dvec3(field.lowers()[i]) + 0.5 * w - p;
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) d[a] -= period[a] * std::round(d[a] / period[a]);
    const glm::dvec3 h = glm::max(glm::dvec3(0.0), 1.0 - glm::abs(d) / w);
    const double weight = h.x * h.y * h.z;
    weightSum += weight;
    for (int c = 0; c < 3; ++c) sum[c] += weight * field.channels()[c].values[i];
  }
  return sum / weightSum;
}

TEST(Periodic, TheSamplerMatchesThePeriodicBruteForceNearEveryFace) {
  std::mt19937_64 rng(11);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    testing::RandomAmrOptions layout;
    layout.levels = 3;
    layout.rootCells = glm::ivec3(3, 2, 2);
    const bricks::AmrField field = testing::randomAmr(seed, layout);
    const PeriodicAxes periodic{true, seed % 2 == 0, true};
    const VectorVolume volume =
        buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"}, testing::periodicVolume(periodic));
    EXPECT_GT(volume.bricks.size(), volume.originalBrickCount) << "no periodic images";
    const glm::vec3 lo(field.bounds().lower), hi(field.bounds().upper);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int k = 0; k < 400; ++k) {
      glm::vec3 p = lo + glm::vec3(u(rng), u(rng), u(rng)) * (hi - lo);
      // Most points within two cells of a face, where the far side contributes.
      const int axis = k % 3;
      if (k % 4 != 0) p[axis] = k % 2 ? lo[axis] + 2.0f * u(rng) : hi[axis] - 2.0f * u(rng);
      p = glm::min(p, glm::vec3(std::nextafter(hi.x, 0.0f), std::nextafter(hi.y, 0.0f),
                                std::nextafter(hi.z, 0.0f)));
      const VectorSample s = sampleVector(volume, p);
      ASSERT_TRUE(s.valid) << "seed " << seed << " p " << p.x << "," << p.y << "," << p.z;
      const glm::dvec3 expected = periodicBruteForce(field, periodic, glm::dvec3(p));
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(s.value[c], expected[c], 2e-5) << "seed " << seed << " component " << c;
    }
  }
}

TEST(Periodic, WrapMovesPointsByWholePeriodsOntoTheHalfOpenDomain) {
  testing::RandomAmrOptions layout;
  layout.levels = 1;
  layout.rootCells = glm::ivec3(8, 4, 4);
  const VectorVolume volume =
      buildVectorVolume(testing::randomAmr(1, layout), {{"vx", "vy", "vz"}, "v"},
                        testing::periodicVolume(flow::PeriodicAxes{true, false, false}));
  const auto wrapped = [&](glm::vec3 p) { return toCellUnits(wrapPeriodic(volume, p)); };
  EXPECT_EQ(wrapped({8.25f, 1.0f, 1.0f}), glm::dvec3(0.25, 1.0, 1.0));
  EXPECT_EQ(wrapped({-0.5f, 1.0f, 1.0f}), glm::dvec3(7.5, 1.0, 1.0));
  EXPECT_EQ(wrapped({8.0f, 5.0f, -1.0f}), glm::dvec3(0.0, 5.0, -1.0));
  // Just below the lower face: the anchor moves by the period, so the point stays exact, inside
  // the half-open domain.
  EXPECT_EQ(wrapped({-1e-7f, 1.0f, 1.0f}).x, 8.0 + double(-1e-7f));
}

// RK4 in double on the analytic ABC field, in the generator's coordinates (unit cube).
glm::dvec3 abcStep(glm::dvec3 x, double dt) {
  const auto v = [](glm::dvec3 p) { return synth::AbcField::velocity(p); };
  const glm::dvec3 k1 = v(x), k2 = v(x + 0.5 * dt * k1), k3 = v(x + 0.5 * dt * k2),
                   k4 = v(x + dt * k3);
  return x + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

TEST(Periodic, AbcTracesCrossEveryFaceAndFollowTheAnalyticStreamline) {
  const bricks::AmrField field =
      synth::generate("abc", {.levels = 3, .rootBlocks = 4, .targetCells = 400000});
  const VectorVolume volume =
      buildVectorVolume(field, chooseVectorChannels(field, ""),
                        testing::periodicVolume(flow::PeriodicAxes{true, true, true}));
  constexpr std::uint64_t kCompared = 200;
  TraceOptions options;
  options.stepMode = StepMode::Time;
  options.stepSize = 2e-3f;
  options.maxSteps = 3000;
  options.direction = Direction::Forward;
  // Seeds next to the faces, so that the lines cross them early on.
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < 12; ++i) {
    glm::dvec3 seed(0.1 + 0.07 * i, 0.9 - 0.065 * i, 0.3 + 0.05 * i);
    seed[i % 3] = i % 2 ? 0.01 : 0.99;
    seeds.push_back(seed);
  }
  const TraceSet t = traceStreamlines(volume, seeds, options);
  std::array<int, 3> crossings{};
  int earlyCrossings = 0;
  double worst = 0.0;
  for (std::size_t line = 0; line < t.lineCount(); ++line) {
    EXPECT_EQ(t.reasons[line], AMRSTREAM_REASON_MAX_STEPS) << "line " << line;
    glm::dvec3 exact = seeds[line], shift(0.0);
    glm::dvec3 previous(t.positions[t.firstPoint(line)]);
    for (std::uint64_t k = 1; k < t.pointCount(line); ++k) {
      const glm::dvec3 a(t.positions[t.firstPoint(line) + k - 1]),
          b(t.positions[t.firstPoint(line) + k]);
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_GE(b[axis], 0.0);
        ASSERT_LT(b[axis], 1.0);
        if (std::abs(b[axis] - a[axis]) > 0.5) {
          ++crossings[axis];
          earlyCrossings += k <= kCompared;
          shift[axis] += b[axis] < a[axis] ? 1.0 : -1.0;
        }
      }
      // Unwrapped, the line is continuous: every step moves less than 0.01 of the box.
      const glm::dvec3 unwrapped = b + shift;
      ASSERT_LT(glm::length(unwrapped - previous), 0.01) << "line " << line << " point " << k;
      previous = unwrapped;
      exact = abcStep(exact, options.stepSize);
      if (k <= kCompared) worst = std::max(worst, glm::length(unwrapped - exact));
    }
  }
  for (int axis = 0; axis < 3; ++axis) EXPECT_GT(crossings[axis], 0) << "axis " << axis;
  EXPECT_GE(earlyCrossings, 8) << "most lines should cross a face while compared";
  // The reconstruction is not exact for this field and its error adds up along the line, faster
  // as the flow is chaotic; over the compared steps it stays within a few finest cells, on
  // either side of the faces.
  EXPECT_LT(worst, 3.0 * volume.transform.spacing.x);
}

}  // namespace
}  // namespace amrstream::flow
