#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <random>

#include "oracles.hpp"
#include "random_amr.hpp"

namespace amrstream::testing {
namespace {

using bricks::BrickSet;
using bricks::buildBricks;

bricks::AmrField uniformGrid(glm::ivec3 cells, glm::ivec3 origin, int level) {
  std::vector<glm::ivec3> lowers;
  for (int z = 0; z < cells.z; ++z)
    for (int y = 0; y < cells.y; ++y)
      for (int x = 0; x < cells.x; ++x)
        lowers.push_back(origin + (1 << level) * glm::ivec3(x, y, z));
  return makeField(lowers, std::vector<std::uint8_t>(lowers.size(), std::uint8_t(level)));
}

// A block-structured layout as codes like FLASH write it: blocks of 8^3 level-1 cells on a grid
// of blocks, some refined into 8 blocks of 8^3 level-0 cells. Cells are listed in shuffled order.
struct BlockLayout {
  bricks::AmrField field;
  std::size_t blocks;
};

BlockLayout blockStructured(std::uint64_t seed, int blocksPerAxis, glm::ivec3 origin) {
  std::mt19937_64 rng(seed);
  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
  std::size_t blocks = 0;
  for (int bz = 0; bz < blocksPerAxis; ++bz)
    for (int by = 0; by < blocksPerAxis; ++by)
      for (int bx = 0; bx < blocksPerAxis; ++bx) {
        const glm::ivec3 corner = origin + 16 * glm::ivec3(bx, by, bz);
        const int level = rng() % 3 == 0 ? 0 : 1;
        blocks += level == 0 ? 8 : 1;
        const int cells = 16 >> level;
        for (int z = 0; z < cells; ++z)
          for (int y = 0; y < cells; ++y)
            for (int x = 0; x < cells; ++x) {
              lowers.push_back(corner + (1 << level) * glm::ivec3(x, y, z));
              levels.push_back(std::uint8_t(level));
            }
      }
  std::vector<std::size_t> order(lowers.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<glm::ivec3> shuffledLowers;
  std::vector<std::uint8_t> shuffledLevels;
  for (std::size_t i : order) {
    shuffledLowers.push_back(lowers[i]);
    shuffledLevels.push_back(levels[i]);
  }
  return {makeField(shuffledLowers, shuffledLevels), blocks};
}

TEST(BuildBricks, SingleCellIsOneBrick) {
  const auto field = makeField({{-4, 8, 12}}, {2});
  const BrickSet set = buildBricks(field);
  ASSERT_EQ(set.bricks.size(), 1u);
  EXPECT_EQ(set.bricks[0].lower, glm::ivec3(-4, 8, 12));
  EXPECT_EQ(set.bricks[0].level, 2);
  EXPECT_EQ(set.bricks[0].size, glm::ivec3(1));
  EXPECT_EQ(set.bricks[0].valueOffset, 0u);
  EXPECT_EQ(set.cellIds, std::vector<std::uint32_t>{0});
}

TEST(BrickDomainDoubled, PadsByHalfACellOfTheBrickLevel) {
  const shared::Brick brick{{-4, 8, 12}, 2, {3, 1, 2}, 0};
  const CellBox d = bricks::brickDomainDoubled(brick);
  // Cells 4 wide: bounds [-4, 8) x [8, 12) x [12, 20), padded by 2, doubled.
  EXPECT_EQ(d.lower, glm::ivec3(-12, 12, 20));
  EXPECT_EQ(d.upper, glm::ivec3(20, 28, 44));
}

TEST(BuildBricks, UniformGridSplitsIntoCapSizedBricks) {
  for (const glm::ivec3 origin : {glm::ivec3(0), glm::ivec3(3, -5, 7)}) {
    const auto field = uniformGrid(glm::ivec3(16), origin, 0);
    const BrickSet set = buildBricks(field, {8});
    EXPECT_TRUE(bricksAreValid(field, set, 8));
    ASSERT_EQ(set.bricks.size(), 8u);
    for (const shared::Brick& b : set.bricks) EXPECT_EQ(b.size, glm::ivec3(8));
    EXPECT_EQ(buildBricks(field, {32}).bricks.size(), 1u);
  }
  const auto field = uniformGrid({40, 8, 8}, glm::ivec3(0), 0);  // 32 + 8 rather than 20 + 20
  EXPECT_EQ(buildBricks(field, {32}).bricks.size(), 2u);
}

TEST(BuildBricks, BlockStructuredLayoutKeepsTheBlocks) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const glm::ivec3 origin = seed % 2 ? glm::ivec3(0) : glm::ivec3(-32, 16, 48);
    const BlockLayout layout = blockStructured(seed, 4, origin);
    const BrickSet set = buildBricks(layout.field, {8});
    EXPECT_TRUE(bricksAreValid(layout.field, set, 8));
    EXPECT_EQ(set.bricks.size(), layout.blocks) << "seed " << seed;
    for (const shared::Brick& b : set.bricks) EXPECT_EQ(b.size, glm::ivec3(8));
    const BrickSet merged = buildBricks(layout.field, {32});
    EXPECT_TRUE(bricksAreValid(layout.field, merged, 32));
    EXPECT_LT(merged.bricks.size(), layout.blocks);
  }
}

// Levels of more than 2^20 cells are bounded and partitioned on all cores, block by block (a
// split's two sides then come in another order): the bricks are as valid, the blocks stay whole,
// and one core builds the same bricks.
TEST(BuildBricks, LargeLevelsSplitOnAllCoresAsOnOne) {
  const BlockLayout layout = blockStructured(5, 14, glm::ivec3(-64, 0, 32));
  ASSERT_GT(layout.field.cellsPerLevel()[0], std::size_t(1) << 20);
  const BrickSet set = buildBricks(layout.field, {8});
  EXPECT_TRUE(bricksAreValid(layout.field, set, 8));
  EXPECT_EQ(set.bricks.size(), layout.blocks);
  tbb::global_control serial(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_TRUE(identical(set, buildBricks(layout.field, {8})));
}

TEST(BuildBricks, LevelJumpOfThreeAcrossAFace) {
  const auto field = levelJumpOfThree();
  const BrickSet set = buildBricks(field, {8});
  EXPECT_TRUE(bricksAreValid(field, set, 8));
  EXPECT_EQ(set.bricks.size(), 2u);
}

TEST(BuildBricks, ScatteredClumpsStayWhole) {
  // 2x2x2 clumps of level-0 cells far apart: nodes far sparser than their extent.
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> coord(-50000, 50000);
  std::vector<glm::ivec3> lowers;
  for (int clump = 0; clump < 300; ++clump) {
    const glm::ivec3 corner = 4 * glm::ivec3(coord(rng), coord(rng), coord(rng));
    for (int i = 0; i < 8; ++i) lowers.push_back(corner + glm::ivec3(i & 1, (i >> 1) & 1, i >> 2));
  }
  const auto field = makeField(lowers, std::vector<std::uint8_t>(lowers.size(), 0));
  const BrickSet set = buildBricks(field, {2});
  EXPECT_TRUE(bricksAreValid(field, set, 2));
  EXPECT_EQ(set.bricks.size(), 300u);
}

TEST(BuildBricks, PeelingLayoutHitsTheDepthLimit) {
  // Cells at powers of two along each axis: every gap split peels off one cell, so the kd
  // recursion would be as deep as the cell count without the depth limit.
  const auto field = powersOfTwoAlongTheAxes();
  for (const int maxSide : {1, 4}) {
    const BrickSet set = buildBricks(field, {maxSide});
    EXPECT_TRUE(bricksAreValid(field, set, maxSide));
  }
}

TEST(BuildBricks, RandomLayoutsGiveValidBricks) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed)
    for (int levels = 1; levels <= 5; ++levels) {
      const auto field = variedRandomLayout(seed, levels);
      for (const int maxSide : {1, 2, 3, 8, 32}) {
        const BrickSet set = buildBricks(field, {maxSide});
        EXPECT_TRUE(bricksAreValid(field, set, maxSide))
            << "seed " << seed << " levels " << levels << " maxSide " << maxSide;
      }
    }
}

TEST(BuildBricks, GatherFollowsCellIds) {
  const auto field = randomAmr(7, {.levels = 4, .rootCells = {3, 2, 3}});
  const BrickSet set = buildBricks(field, {4});
  const auto& channel = field.channel("vy");
  const std::vector<float> values = set.gather(channel);
  ASSERT_EQ(values.size(), field.cellCount());
  for (std::size_t slot = 0; slot < values.size(); ++slot)
    EXPECT_EQ(values[slot], channel.values[set.cellIds[slot]]);
  EXPECT_THROW(set.gather(Channel{"short", {1.0f}}), std::invalid_argument);
}

TEST(BuildBricks, OutputIsDeterministic) {
  const auto field = randomAmr(11, {.levels = 5, .rootCells = {6, 5, 6}, .refineProbability = 0.5});
  const BrickSet first = buildBricks(field, {4});
  EXPECT_TRUE(identical(first, buildBricks(field, {4})));
  tbb::global_control serial(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_TRUE(identical(first, buildBricks(field, {4})));
}

TEST(BuildBricks, RejectsNonPositiveCap) {
  const auto field = makeField({{0, 0, 0}}, {0});
  EXPECT_THROW(buildBricks(field, {0}), std::invalid_argument);
}

}  // namespace
}  // namespace amrstream::testing
