#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "oracles.hpp"
#include "random_amr.hpp"

namespace amrstream::testing {
namespace {

using bricks::buildBricks;
using bricks::buildRegions;
using bricks::RegionSet;

// Builds bricks and regions and runs every oracle on them.
RegionSet checkLayout(const bricks::AmrField& field, int maxSide, std::uint64_t seed,
                      int points = 600) {
  const bricks::BrickSet set = buildBricks(field, {maxSide});
  RegionSet regions = buildRegions(set.bricks);
  EXPECT_TRUE(regionsAreValid(set.bricks, regions));
  EXPECT_TRUE(
      locateMatchesBruteForce(set.bricks, regions, probePoints(set.bricks, regions, seed, points)));
  return regions;
}

std::vector<std::uint32_t> bricksAt(const RegionSet& regions, glm::vec3 p) {
  const std::int32_t r = locateCellUnits(regions, p);
  if (r < 0) return {};
  const shared::Region& region = regions.regions[r];
  return {regions.regionBricks.begin() + region.brickOffset,
          regions.regionBricks.begin() + region.brickOffset + region.brickCount};
}

float finestWidthAt(const RegionSet& regions, glm::vec3 p) {
  const std::int32_t r = locateCellUnits(regions, p);
  return r < 0 ? -1.0f : regions.regions[r].finestCellWidth;
}

TEST(BuildRegions, SingleCellIsOneRegion) {
  const auto field = makeField({{-4, 8, 12}}, {2});
  const RegionSet regions = checkLayout(field, 8, 1);
  ASSERT_EQ(regions.regions.size(), 1u);
  ASSERT_EQ(regions.tree.size(), 1u);
  EXPECT_EQ(regions.lower, glm::ivec3(-12, 12, 20));  // the region lattice: doubled
  EXPECT_EQ(regions.upper, glm::ivec3(4, 28, 36));
  EXPECT_EQ(regions.regions[0].finestCellWidth, 4.0f);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{-6, 6, 10}), 0);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{1.99f, 13.99f, 17.99f}), 0);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{2, 10, 14}), -1);  // the upper face is outside
}

TEST(BuildRegions, LevelJumpOfThreeAcrossAFace) {
  const auto field = levelJumpOfThree();
  const bricks::BrickSet set = buildBricks(field, {8});
  ASSERT_EQ(set.bricks.size(), 2u);
  const RegionSet regions = checkLayout(field, 8, 2, 2000);
  // Coarse domain [-4, 12)^3, fine domain [7.5, 16.5) x [-0.5, 8.5)^2.
  EXPECT_EQ(bricksAt(regions, {7.25f, 4, 4}).size(), 1u);
  EXPECT_EQ(bricksAt(regions, {7.5f, 4, 4}).size(), 2u);
  EXPECT_EQ(finestWidthAt(regions, {7.5f, 4, 4}), 1.0f);
  EXPECT_EQ(finestWidthAt(regions, {7.25f, 4, 4}), 8.0f);
  EXPECT_EQ(bricksAt(regions, {12, 4, 4}).size(), 1u);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{16.5f, 4, 4}), -1);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{14, 10, 4}),
            -1);  // above the fine block, outside all domains
}

TEST(BuildRegions, FineCellsOnTheDomainBoundary) {
  // Two level-2 cells; the lower corner one refined into level-0 cells touching the boundary.
  std::vector<glm::ivec3> lowers{{4, 0, 0}};
  std::vector<std::uint8_t> levels{2};
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) {
        lowers.push_back({x, y, z});
        levels.push_back(0);
      }
  const RegionSet regions = checkLayout(makeField(lowers, levels), 8, 3, 2000);
  EXPECT_EQ(regions.lower, glm::ivec3(-1, -4, -4));  // the coarse cell pads y and z by 2
  EXPECT_EQ(regions.upper, glm::ivec3(20, 12, 12));
  EXPECT_GE(locateCellUnits(regions, glm::vec3{-0.5f, 0, 0}),
            0);  // the root box's lower face is inside
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{-0.5f, 0, 0}),
            locateCellUnits(regions, glm::vec3{-0.25f, 0.25f, 0.25f}));
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{-0.5f, -1, 0}),
            -1);  // in the root box but in no domain
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{10, 1, 1}), -1);
}

TEST(BuildRegions, HoleLeavesEmptySpace) {
  // A shell of level-0 cells, 5^3 minus the central 3^3; padding covers only half a cell.
  std::vector<glm::ivec3> lowers;
  for (int z = 0; z < 5; ++z)
    for (int y = 0; y < 5; ++y)
      for (int x = 0; x < 5; ++x)
        if (glm::any(glm::equal(glm::ivec3(x, y, z), glm::ivec3(0))) ||
            glm::any(glm::equal(glm::ivec3(x, y, z), glm::ivec3(4))))
          lowers.push_back({x, y, z});
  ASSERT_EQ(lowers.size(), 98u);
  const auto field = makeField(lowers, std::vector<std::uint8_t>(lowers.size(), 0));
  for (const int maxSide : {1, 2, 5}) {
    const RegionSet regions = checkLayout(field, maxSide, 4, 2000);
    EXPECT_EQ(locateCellUnits(regions, glm::vec3{2.5f, 2.5f, 2.5f}), -1);
    EXPECT_EQ(locateCellUnits(regions, glm::vec3{1.5f, 1.5f, 1.5f}), -1);
    EXPECT_GE(locateCellUnits(regions, glm::vec3{1.49f, 2.5f, 2.5f}), 0);
  }
  // Two clusters far apart: the gap between them is in no region.
  const auto apart = makeField({{0, 0, 0}, {64, 0, 0}, {64, 64, 64}}, {3, 3, 2});
  const RegionSet regions = checkLayout(apart, 8, 5, 2000);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{32, 4, 4}), -1);
}

TEST(BuildRegions, RandomLayoutsTileTheDomains) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed)
    for (int levels = 1; levels <= 5; ++levels) {
      const auto field = variedRandomLayout(seed, levels);
      for (const int maxSide : {1, 3, 32}) {
        SCOPED_TRACE(::testing::Message()
                     << "seed " << seed << " levels " << levels << " maxSide " << maxSide);
        checkLayout(field, maxSide, seed * 100 + levels, 300);
      }
    }
}

TEST(BuildRegions, ManyBricksBuiltInParallelChunks) {
  // maxBrickSide 1 makes every cell a brick: enough bricks for the parallel chunk path.
  const auto field = randomAmr(
      21,
      {.levels = 4, .rootCells = {5, 4, 5}, .refineProbability = 0.75, .origin = {-8, 16, -24}});
  const bricks::BrickSet set = buildBricks(field, {1});
  ASSERT_GT(set.bricks.size(), 3 * 4096u);
  const RegionSet regions = buildRegions(set.bricks);
  EXPECT_TRUE(regionsAreValid(set.bricks, regions));
  EXPECT_TRUE(
      locateMatchesBruteForce(set.bricks, regions, probePoints(set.bricks, regions, 9, 400)));
}

TEST(BuildRegions, OutputIsDeterministic) {
  const auto field = randomAmr(13, {.levels = 5, .rootCells = {4, 4, 3}, .refineProbability = 0.5});
  const bricks::BrickSet set = buildBricks(field, {1});
  ASSERT_GT(set.bricks.size(), 2 * 4096u);
  const RegionSet first = buildRegions(set.bricks);
  EXPECT_TRUE(identical(first, buildRegions(set.bricks)));
  tbb::global_control serial(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_TRUE(identical(first, buildRegions(set.bricks)));
}

TEST(BuildRegions, FarApartBricksInAHugeBox) {
  // Cells at powers of two along each axis up to 2^19: too large for the voxel oracle, so
  // locate() is checked against brute force on domain corners, faces and random points.
  const auto field = powersOfTwoAlongTheAxes();
  const bricks::BrickSet set = buildBricks(field, {1});
  const RegionSet regions = buildRegions(set.bricks);
  EXPECT_TRUE(
      locateMatchesBruteForce(set.bricks, regions, probePoints(set.bricks, regions, 6, 4000)));
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{1000, 1000, 1000}), -1);
}

TEST(BuildRegions, LatticeFitsThirtyTwoBitsOrIsRefused) {
  // Doubled coordinates: a corner at 2^30 - 2 pads to just under 2^31.
  const shared::Brick inRange{{(1 << 30) - 2, 0, 0}, 0, {1, 1, 1}, 0};
  const RegionSet near = buildRegions({inRange});
  EXPECT_EQ(near.upper.x, (1 << 30) * 2 - 1);
  EXPECT_EQ(locateCellUnits(near, glm::vec3{0, 0, 0}), -1);
  const shared::Brick beyond{{1 << 30, 0, 0}, 0, {1, 1, 1}, 0};
  EXPECT_THROW(buildRegions({beyond}), std::invalid_argument);
  const shared::Brick farBelow{{-(1 << 30), 0, 0}, 4, {1, 1, 1}, 0};
  EXPECT_THROW(buildRegions({farBelow}), std::invalid_argument);
  // Clipped to a domain, a periodic image a period away keeps the part that reaches in.
  const shared::Brick image{{1 << 29, 0, 0}, 28, {2, 1, 1}, 0};
  const CellBox domain{{-(1 << 29), 0, 0}, {1 << 29, 1 << 28, 1 << 28}};
  const RegionSet clipped = buildRegions({image}, domain);
  EXPECT_EQ(clipped.lower.x, 2 * (1 << 29) - (1 << 28));
  EXPECT_EQ(clipped.upper.x, 2 * (1 << 29) + (1 << 28));
}

TEST(BuildRegions, NoBricksAndBadPointsLocateNothing) {
  const RegionSet empty = buildRegions({});
  EXPECT_EQ(locateCellUnits(empty, glm::vec3{0, 0, 0}), -1);
  EXPECT_TRUE(empty.regions.empty());

  const RegionSet regions = buildRegions(buildBricks(makeField({{0, 0, 0}}, {1})).bricks);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{NAN, 0.5f, 0.5f}), -1);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{INFINITY, 0.5f, 0.5f}), -1);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{-1e30f, 0.5f, 0.5f}), -1);
  EXPECT_EQ(locateCellUnits(regions, glm::vec3{0.5f, 0.5f, 0.5f}), 0);
}

}  // namespace
}  // namespace amrstream::testing
