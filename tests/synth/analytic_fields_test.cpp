// rotation and abc: every cell holds the analytic formula at its centre, and the finest cells
// sit on the feature each kind refines (the ring streamline, the stagnation points).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include "synth/abc_field.hpp"
#include "synth/generators.hpp"
#include "synth/rotation_field.hpp"

namespace amrstream::synth {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec3 centreOf(const bricks::AmrField& f, std::size_t i) {
  const double w = bricks::AmrField::cellWidth(f.levels()[i]);
  return f.transform().toPhysical(glm::dvec3(f.lowers()[i]) + 0.5 * w);
}

glm::dvec3 valueOf(const bricks::AmrField& f, std::size_t i) {
  return {f.channel("velx").values[i], f.channel("vely").values[i], f.channel("velz").values[i]};
}

std::optional<std::size_t> cellContaining(const bricks::AmrField& f, glm::dvec3 p) {
  const glm::dvec3 q = f.transform().toCellUnits(p);
  for (std::size_t i = 0; i < f.cellCount(); ++i) {
    const glm::dvec3 lower(f.lowers()[i]);
    const glm::dvec3 upper = lower + double(bricks::AmrField::cellWidth(f.levels()[i]));
    if (glm::all(glm::lessThanEqual(lower, q)) && glm::all(glm::lessThan(q, upper))) return i;
  }
  return std::nullopt;
}

// Float storage: values up to ~4.5 are rounded to within 2.4e-7.
constexpr double kFloatTolerance = 1e-6;

TEST(RotationGenerator, EveryCellHoldsOmegaCrossR) {
  const bricks::AmrField f = generate("rotation", BuiltinOptions{4, 2, 60'000});
  for (std::size_t i = 0; i < f.cellCount(); ++i) {
    const glm::dvec3 c = centreOf(f, i);
    const glm::dvec3 expected(-2.0 * kPi * (c.y - 0.5), 2.0 * kPi * (c.x - 0.5), 0.0);
    const glm::dvec3 v = valueOf(f, i);
    ASSERT_NEAR(v.x, expected.x, kFloatTolerance) << "cell " << i;
    ASSERT_NEAR(v.y, expected.y, kFloatTolerance) << "cell " << i;
    ASSERT_EQ(v.z, 0.0) << "cell " << i;
  }
}

TEST(RotationGenerator, TheRingIsOnTheFinestLevel) {
  const bricks::AmrField f = generate("rotation", BuiltinOptions{3, 2, 130'000});
  ASSERT_EQ(f.finestLevel(), 0);
  ASSERT_GT(f.coarsestLevel(), 0);
  for (int k = 0; k < 64; ++k) {
    const double angle = 2.0 * kPi * (k + 0.5) / 64;
    const glm::dvec3 p(0.5 + 0.25 * std::cos(angle), 0.5 + 0.25 * std::sin(angle), 0.5);
    EXPECT_NEAR(RotationField::distanceToRing(p), 0.0, 1e-12);
    const std::optional<std::size_t> cell = cellContaining(f, p);
    ASSERT_TRUE(cell);
    EXPECT_EQ(f.levels()[*cell], 0) << "ring point " << k;
  }
}

TEST(AbcGenerator, EveryCellHoldsTheAbcFormula) {
  const double a = std::sqrt(3.0), b = std::sqrt(2.0), c = 1.0;
  const bricks::AmrField f = generate("abc", BuiltinOptions{4, 2, 60'000});
  for (std::size_t i = 0; i < f.cellCount(); ++i) {
    const glm::dvec3 x = 2.0 * kPi * centreOf(f, i);
    const glm::dvec3 expected(a * std::sin(x.z) + c * std::cos(x.y),
                              b * std::sin(x.x) + a * std::cos(x.z),
                              c * std::sin(x.y) + b * std::cos(x.x));
    const glm::dvec3 v = valueOf(f, i);
    for (int d = 0; d < 3; ++d) ASSERT_NEAR(v[d], expected[d], kFloatTolerance) << "cell " << i;
  }
}

TEST(AbcGenerator, AStagnationPointIsOnTheFinestLevel) {
  const glm::dvec3 stagnation(0.25, 0.5, (kPi - std::asin(1.0 / std::sqrt(3.0))) / (2.0 * kPi));
  ASSERT_LT(glm::length(AbcField::velocity(stagnation)), 1e-12);
  const bricks::AmrField f = generate("abc", BuiltinOptions{5, 2, 250'000});
  ASSERT_EQ(f.finestLevel(), 0);
  const std::optional<std::size_t> cell = cellContaining(f, stagnation);
  ASSERT_TRUE(cell);
  EXPECT_EQ(f.levels()[*cell], 0);
  // And the slow cells are the fine ones: mean speed rises with the level.
  std::vector<double> speed(f.coarsestLevel() + 1, 0.0);
  const std::vector<std::size_t> perLevel = f.cellsPerLevel();
  for (std::size_t i = 0; i < f.cellCount(); ++i)
    speed[f.levels()[i]] += glm::length(valueOf(f, i));
  EXPECT_LT(speed.front() / perLevel.front(), speed.back() / perLevel.back());
}

}  // namespace
}  // namespace amrstream::synth
