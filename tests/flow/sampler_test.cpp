// The sampler against the definition: the brute-force sum of tent functions over all cells.

#include "flow/sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "flow_test_support.hpp"

namespace amrstream::flow {
namespace {

struct BruteForce {
  glm::dvec3 value{0.0};
  double weightSum = 0.0;
  int contributing = 0;
  bool singleLevel = true;
};

// B(p) = sum_i H_i(p) v_i / sum_i H_i(p) over every cell, in double precision.
BruteForce bruteForceSample(const bricks::AmrField& field, glm::dvec3 p) {
  BruteForce r;
  int level = -1;
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const double w = bricks::AmrField::cellWidth(field.levels()[i]);
    const glm::dvec3 centre = glm::dvec3(field.lowers()[i]) + 0.5 * w;
    const glm::dvec3 h = glm::max(glm::dvec3(0.0), 1.0 - glm::abs(centre - p) / w);
    const double weight = h.x * h.y * h.z;
    if (weight <= 0.0) continue;
    ++r.contributing;
    if (level >= 0 && level != field.levels()[i]) r.singleLevel = false;
    level = field.levels()[i];
    r.weightSum += weight;
    for (int c = 0; c < 3; ++c) r.value[c] += weight * field.channels()[c].values[i];
  }
  if (r.weightSum > 0.0) r.value /= r.weightSum;
  return r;
}

glm::vec3 randomPointIn(const CellBox& box, std::mt19937_64& rng) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const glm::vec3 lo(box.lower), hi(box.upper);
  glm::vec3 p = lo + glm::vec3(u(rng), u(rng), u(rng)) * (hi - lo);
  return glm::min(p, glm::vec3(std::nextafter(hi.x, lo.x), std::nextafter(hi.y, lo.y),
                               std::nextafter(hi.z, lo.z)));
}

TEST(Sampler, MatchesBruteForceOnRandomLayouts) {
  std::mt19937_64 rng(42);
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    testing::RandomAmrOptions options;
    options.levels = 1 + int(seed % 5);
    options.origin = glm::ivec3(-(1 << (options.levels - 1)), 0, 0);
    const bricks::AmrField field = testing::randomAmr(seed, options);
    const VectorVolume volume = testing::volumeOf(field);
    for (int k = 0; k < 300; ++k) {
      // Half the points on lattice planes (cell faces and centres) where ties are likeliest.
      glm::vec3 p = randomPointIn(field.bounds(), rng);
      if (k % 2) p = glm::floor(p * 2.0f) * 0.5f;
      const VectorSample s = sampleVector(volume, p);
      const BruteForce expected = bruteForceSample(field, glm::dvec3(p));
      ASSERT_TRUE(s.located) << "seed " << seed << " p " << p.x << "," << p.y << "," << p.z;
      ASSERT_TRUE(s.valid);
      for (int c = 0; c < 3; ++c)  // values in [-1, 1]: agreement to float rounding
        ASSERT_NEAR(s.value[c], expected.value[c], 2e-6)
            << "seed " << seed << " p " << p.x << "," << p.y << "," << p.z;
    }
  }
}

TEST(Sampler, IsExactOnConstantFieldsAcrossLevels) {
  const glm::vec3 constant(0.75f, -2.5f, 1e3f);
  testing::RandomAmrOptions options;
  options.levels = 5;
  const bricks::AmrField field =
      testing::randomAmr(5, options, [&](glm::dvec3) { return constant; });
  const VectorVolume volume = testing::volumeOf(field);
  std::mt19937_64 rng(1);
  for (int k = 0; k < 2000; ++k) {
    const VectorSample s = sampleVector(volume, randomPointIn(field.bounds(), rng));
    ASSERT_TRUE(s.valid);
    // A convex combination of equal floats: exact up to the rounding of the final division.
    ASSERT_NEAR(s.value.x, constant.x, 1e-6f * std::abs(constant.x));
    ASSERT_NEAR(s.value.y, constant.y, 1e-6f * std::abs(constant.y));
    ASSERT_NEAR(s.value.z, constant.z, 1e-6f * std::abs(constant.z));
  }
}

glm::vec3 linear(glm::dvec3 p) {
  return glm::vec3(0.5 + 0.01 * p.x - 0.02 * p.y, -0.3 + 0.015 * p.z,
                   0.2 + 0.01 * (p.x + p.y + p.z));
}

TEST(Sampler, IsExactOnLinearFieldsInsideOneLevel) {
  const bricks::AmrField field = testing::uniformGrid(12, linear);
  const VectorVolume volume = testing::volumeOf(field);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> u(0.5f, 11.5f);  // between the outermost cell centres
  for (int k = 0; k < 2000; ++k) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    const VectorSample s = sampleVector(volume, p);
    ASSERT_TRUE(s.valid);
    const glm::vec3 expected = linear(glm::dvec3(p));
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(s.value[c], expected[c], 2e-6f);
  }
}

TEST(Sampler, IsExactOnLinearFieldsWhereTheStencilIsOneFullLevelOfAMultiLevelLayout) {
  testing::RandomAmrOptions options;
  options.levels = 3;
  options.rootCells = glm::ivec3(5);
  options.refineProbability = 0.3;  // large patches of one level
  const bricks::AmrField field = testing::randomAmr(11, options, linear);
  const VectorVolume volume = testing::volumeOf(field);
  std::mt19937_64 rng(4);
  int checked = 0;
  for (int k = 0; k < 4000; ++k) {
    const glm::vec3 p = randomPointIn(field.bounds(), rng);
    const BruteForce stencil = bruteForceSample(field, glm::dvec3(p));
    if (!stencil.singleLevel || stencil.contributing != 8) continue;
    ++checked;
    const VectorSample s = sampleVector(volume, p);
    const glm::vec3 expected = linear(glm::dvec3(p));
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(s.value[c], expected[c], 4e-6f);
  }
  EXPECT_GT(checked, 200);
}

TEST(Sampler, ReportsRegionCellWidthAndOutOfDomain) {
  testing::RandomAmrOptions options;
  options.levels = 3;
  const bricks::AmrField field = testing::randomAmr(2, options);
  const VectorVolume volume = testing::volumeOf(field);
  const CellBox box = field.bounds();
  EXPECT_FALSE(sampleVector(volume, glm::vec3(box.upper)).located);
  EXPECT_FALSE(sampleVector(volume, glm::vec3(box.lower) - glm::vec3(0.25f, 0, 0)).located);
  EXPECT_FALSE(sampleVector(volume, glm::vec3(box.upper.x, 0.5f, 0.5f)).located);
  const VectorSample corner = sampleVector(volume, glm::vec3(box.lower));
  EXPECT_TRUE(corner.located);
  // The finest width of the region is the width of the finest cell whose tent reaches p
  // or whose padded domain holds it: never more than the width of the cell holding p.
  std::mt19937_64 rng(9);
  for (int k = 0; k < 500; ++k) {
    const glm::vec3 p = randomPointIn(box, rng);
    const VectorSample s = sampleVector(volume, p);
    int holder = -1;
    for (std::size_t i = 0; i < field.cellCount(); ++i) {
      const glm::vec3 lo(field.lowers()[i]);
      if (glm::all(glm::greaterThanEqual(p, lo)) &&
          glm::all(glm::lessThan(p, lo + float(1 << field.levels()[i]))))
        holder = int(i);
    }
    ASSERT_GE(holder, 0);
    EXPECT_LE(s.cellWidth, float(1 << field.levels()[holder]));
  }
}

TEST(Sampler, PointOnTheLowerFaceOfAnIsolatedBricksDomainHasNoWeight) {
  // Two 4^3 blocks with a gap: the second one's domain starts half a cell before x = 8, where
  // every tent function of its cells is zero.
  const bricks::AmrField field = testing::twoBlocksWithAGap();
  const VectorVolume volume = testing::volumeOf(field);
  const VectorSample onFace = sampleVector(volume, glm::vec3(7.5f, 2.0f, 2.0f));
  EXPECT_TRUE(onFace.located);
  EXPECT_FALSE(onFace.valid);
  EXPECT_FALSE(sampleVector(volume, glm::vec3(6.0f, 2.0f, 2.0f)).located);  // in the gap
  EXPECT_TRUE(sampleVector(volume, glm::vec3(7.6f, 2.0f, 2.0f)).valid);
}

}  // namespace
}  // namespace amrstream::flow
