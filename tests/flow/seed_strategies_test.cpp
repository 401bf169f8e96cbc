// Seeding strategies: random seeds in cells, rakes, grids and the densest cells.

#include "flow/seed_strategies.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "flow_test_support.hpp"
#include "input_error_of.hpp"
#include "random_amr.hpp"

namespace amrstream::flow {
namespace {

using ::testing::HasSubstr;

// Brute force over the field's cells: the oracle for insideACell.
bool insideSomeCell(const bricks::AmrField& field, glm::dvec3 p) {
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const glm::dvec3 lower(field.lowers()[i]);
    const double width = bricks::AmrField::cellWidth(field.levels()[i]);
    if (glm::all(glm::greaterThanEqual(p, lower)) && glm::all(glm::lessThan(p, lower + width)))
      return true;
  }
  return false;
}

TEST(SeedStrategies, RandomSeedsLandInCellsNeverInHoles) {
  // Two 4^3 blocks at x = 0..4 and 8..12: the domain box [0, 12) has a hole at 4 <= x < 8.
  const bricks::AmrField field = testing::twoBlocksWithAGap();
  const VectorVolume volume = testing::volumeOf(field);
  const SeedList seeds = randomSeedsInCells(volume, {0, 0, 0}, {12, 4, 4}, 500, 5);
  ASSERT_EQ(seeds.points.size(), 500u);
  std::size_t inSecondBlock = 0;
  for (const glm::dvec3& p : seeds.points) {
    ASSERT_TRUE(insideSomeCell(field, p)) << p.x << " " << p.y << " " << p.z;
    inSecondBlock += p.x >= 8.0;
  }
  EXPECT_GT(inSecondBlock, 150u);  // both blocks are seeded, about half each
  EXPECT_LT(inSecondBlock, 350u);
  for (double x = 0.0; x < 12.0; x += 0.25) {
    const glm::dvec3 p(x, 1.3, 2.7);
    EXPECT_EQ(insideACell(volume, p), insideSomeCell(field, p)) << x;
  }
}

TEST(SeedStrategies, InsideACellOfAFieldWithoutHolesAnswersAsTheRegionLookupDoes) {
  // Random 4-level layouts fill their domain box, so that a point in the box is in a cell. The
  // region lookup sees points in float: within 2^-24 cells under an upper face it finds none.
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const bricks::AmrField field = testing::randomAmr(seed, {4, {2, 3, 2}, 0.45, {16, -8, 0}});
    const VectorVolume filled = testing::volumeOf(field);
    VectorVolume lookedUp = testing::volumeOf(field);
    EXPECT_TRUE(filled.cellsFillDomain) << seed;
    lookedUp.cellsFillDomain = false;  // every point through the region lookup
    const glm::dvec3 lower(field.bounds().lower), upper(field.bounds().upper);
    ASSERT_EQ(glm::dvec3(filled.domain.lower), lower);  // the field's own cell units
    const std::vector<glm::dvec3> points =
        testing::pointsInAndAroundBox(lower, upper, 0.5, 2000, seed);
    for (const glm::dvec3& p : points) {
      ASSERT_EQ(insideACell(filled, p), insideACell(lookedUp, p))
          << seed << ": " << p.x << " " << p.y << " " << p.z;
      if (glm::all(glm::lessThan(p, upper - 0x1.0p-20))) {
        ASSERT_EQ(insideACell(filled, p), insideSomeCell(field, p))
            << seed << ": " << p.x << " " << p.y << " " << p.z;
      }
    }
  }
  EXPECT_FALSE(testing::volumeOf(testing::twoBlocksWithAGap()).cellsFillDomain);
}

TEST(SeedStrategies, RandomSeedsInCellsEqualTheBoxDrawWithoutHoles) {
  const VectorVolume volume =
      testing::volumeOf(testing::uniformGrid(4, [](glm::dvec3) { return glm::vec3(1.0f); }));
  const SeedList inCells = randomSeedsInCells(volume, {0, 0, 0}, {3.9, 3.9, 3.9}, 100, 11);
  const SeedList inBox = randomSeedsInBox({0, 0, 0}, {3.9, 3.9, 3.9}, 100, 11);
  EXPECT_EQ(inCells.points, inBox.points);
}

TEST(SeedStrategies, RandomSeedsInABoxOfHolesAreRefusedByName) {
  const VectorVolume volume = testing::volumeOf(testing::twoBlocksWithAGap());
  EXPECT_THAT(testing::inputErrorOf([&] {
                randomSeedsInCells(volume, {4.6, 0, 0}, {7.4, 4, 4}, 10, 1);
              }),
              HasSubstr("the box is nearly all holes"));
}

TEST(SeedStrategies, RakeIsEvenlySpacedWithBothEnds) {
  const SeedList rake = seedsAlongLine({0, 0, 0}, {1, 2, 4}, 5);
  ASSERT_EQ(rake.points.size(), 5u);
  EXPECT_EQ(rake.points.front(), glm::dvec3(0, 0, 0));
  EXPECT_EQ(rake.points.back(), glm::dvec3(1, 2, 4));
  EXPECT_EQ(rake.points[2], glm::dvec3(0.5, 1, 2));
  EXPECT_EQ(seedsAlongLine({0, 0, 0}, {2, 2, 2}, 1).points[0], glm::dvec3(1, 1, 1));
}

TEST(SeedStrategies, GridIsCellCentredAndAPlaneWhenFlat) {
  const SeedList grid = seedsOnGrid({0, 0, 0}, {4, 2, 1}, {4, 2, 1});
  ASSERT_EQ(grid.points.size(), 8u);
  EXPECT_EQ(grid.points[0], glm::dvec3(0.5, 0.5, 0.5));
  EXPECT_EQ(grid.points[7], glm::dvec3(3.5, 1.5, 0.5));
  const SeedList plane = seedsOnGrid({0, 0, 0.25}, {1, 1, 0.25}, {10, 10, 1});
  ASSERT_EQ(plane.points.size(), 100u);
  for (const glm::dvec3& p : plane.points) EXPECT_EQ(p.z, 0.25);
}

bricks::AmrField fieldWithDensity() {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  const bricks::AmrField random = testing::randomAmr(2, layout);
  std::vector<float> dens;  // the x coordinate of the cell centre: highest on the +x side
  for (std::size_t i = 0; i < random.cellCount(); ++i)
    dens.push_back(float(random.lowers()[i].x) + 0.5f * float(1 << random.levels()[i]));
  std::vector<Channel> channels = random.channels();
  channels.push_back({"dens", dens});
  return bricks::AmrField({random.lowers().begin(), random.lowers().end()},
                          {random.levels().begin(), random.levels().end()}, channels,
                          {{1.0, 2.0, 3.0}, {0.5, 0.5, 0.5}}, "dens-test");
}

TEST(SeedStrategies, DensestCellsSeedsLieInCellsAboveThePercentile) {
  const bricks::AmrField field = fieldWithDensity();
  const std::vector<float>& dens = field.channel("dens").values;
  std::vector<float> sorted = dens;
  std::sort(sorted.begin(), sorted.end());
  const float threshold = sorted[std::size_t(0.8 * double(sorted.size()))];
  DensestCellsOptions options{"dens", 80.0, false, 2000, 5};
  const SeedList seeds = seedsInDensestCells(field, options);
  ASSERT_EQ(seeds.points.size(), 2000u);
  for (const glm::dvec3& p : seeds.points) {
    const glm::dvec3 c = field.transform().toCellUnits(p);
    bool found = false;
    for (std::size_t i = 0; i < field.cellCount() && !found; ++i) {
      const glm::dvec3 lo(field.lowers()[i]);
      if (glm::all(glm::greaterThanEqual(c, lo)) &&
          glm::all(glm::lessThan(c, lo + double(1 << field.levels()[i])))) {
        found = true;
        EXPECT_GE(dens[i], threshold);
      }
    }
    EXPECT_TRUE(found);
  }
  EXPECT_EQ(seedsInDensestCells(field, options).points, seeds.points);  // reproducible
  options.seed = 6;
  EXPECT_NE(seedsInDensestCells(field, options).points, seeds.points);
}

// The percentile's value is found by histograms of the values' bits: it must be what
// nth_element gives, at every rank, with negatives, both zeros, repeats and large magnitudes,
// over several threads' pieces.
TEST(SeedStrategies, ValueAtRankIsNthElement) {
  std::mt19937 rng(11);
  std::vector<float> values(300000);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::uint32_t r = rng();
    values[i] = r % 7 == 0   ? 0.0f
                : r % 7 == 1 ? -0.0f
                : r % 7 == 2 ? float(int(r % 100) - 50)
                             : std::ldexp(float(r % 1000) - 500.0f, int(r % 60) - 30);
  }
  for (const std::size_t rank :
       {std::size_t(0), std::size_t(1), std::size_t(12345), values.size() / 2,
        values.size() * 9 / 10, values.size() - 2, values.size() - 1}) {
    std::vector<float> sorted = values;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(rank), sorted.end());
    EXPECT_EQ(valueAtRank(values, rank), sorted[rank]) << "rank " << rank;
  }
  EXPECT_EQ(valueAtRank(std::vector<float>{3.5f}, 0), 3.5f);
}

TEST(SeedStrategies, WeightedPicksCellsInProportionToTheirValue) {
  std::vector<float> dens{1.0f, 3.0f};
  const bricks::AmrField field({{0, 0, 0}, {1, 0, 0}}, {0, 0}, {{"dens", dens}}, {}, "two");
  const SeedList seeds = seedsInDensestCells(field, {"dens", 0.0, true, 20000, 3});
  const auto inSecond = std::count_if(seeds.points.begin(), seeds.points.end(),
                                      [](const glm::dvec3& p) { return p.x >= 1.0; });
  EXPECT_NEAR(double(inSecond) / 20000.0, 0.75, 0.015);  // 4.6 standard deviations
}

TEST(SeedStrategies, DensestCellsRejectsBadOptions) {
  const bricks::AmrField field = fieldWithDensity();
  EXPECT_THAT(testing::inputErrorOf([&] {
                seedsInDensestCells(field, {"rho", 90.0});
              }),
              HasSubstr("no channel named 'rho'"));
  EXPECT_THAT(testing::inputErrorOf([&] {
                seedsInDensestCells(field, {"dens", 101.0});
              }),
              HasSubstr("not a percentile"));
  EXPECT_THAT(testing::inputErrorOf([&] {
                seedsInDensestCells(field, {"vx", 0.0, true});
              }),
              HasSubstr("needs positive values"));
}

}  // namespace
}  // namespace amrstream::flow
