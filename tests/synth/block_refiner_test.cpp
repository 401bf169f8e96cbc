// The block octree: budget, level limits, priority order, tie-breaking, exact tiling.

#include "synth/block_refiner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "amrstream/error.hpp"
#include "synth/block_emitter.hpp"

namespace amrstream::synth {
namespace {

constexpr std::size_t kSplitCost = 7 * kBlockCells;

std::size_t rootCells(const BuiltinOptions& o) {
  return std::size_t(o.rootBlocks) * o.rootBlocks * o.rootBlocks * kBlockCells;
}

std::size_t cellCount(const std::vector<Block>& leaves) { return leaves.size() * kBlockCells; }

// A deterministic pseudo-random priority from the block position.
double hashedPriority(const BlockBox& box) {
  const double x = std::sin(12.9898 * box.lower.x + 78.233 * box.lower.y + 37.719 * box.lower.z +
                            4.1 * box.cellWidth) *
                   43758.5453;
  return x - std::floor(x);
}

TEST(BlockRefiner, BudgetOfTheRootGridGivesTheRootGrid) {
  const BuiltinOptions o = BuiltinOptions{3, 2, 8 * kBlockCells};
  const std::vector<Block> leaves = refineBlocks(o, "test", hashedPriority);
  ASSERT_EQ(leaves.size(), 8u);
  for (const Block& b : leaves) {
    EXPECT_EQ(b.level, 2);
    EXPECT_EQ(b.span(), 32);
    EXPECT_EQ(b.lower % 32, glm::ivec3(0));
  }
}

TEST(BlockRefiner, TiesGoToTheCoarserBlockThenToTheLowerMortonKey) {
  // A constant priority: the 8 roots are split first (one level everywhere), then the level-1
  // block at the origin (lowest Morton key).
  const BuiltinOptions o = BuiltinOptions{3, 2, 8 * kBlockCells + 9 * kSplitCost};
  const std::vector<Block> leaves = refineBlocks(o, "test", [](const BlockBox&) { return 1.0; });
  ASSERT_EQ(cellCount(leaves), o.targetCells);
  int fine = 0;
  for (const Block& b : leaves) {
    if (b.level == 0) {
      ++fine;
      EXPECT_TRUE(glm::all(glm::lessThan(b.lower, glm::ivec3(16)))) << b.lower.x;
    } else {
      EXPECT_EQ(b.level, 1);
    }
  }
  EXPECT_EQ(fine, 8);
}

TEST(BlockRefiner, HighestPriorityIsSplitFirst) {
  // Priority falls with the distance to q, so only the blocks containing q are split.
  const glm::dvec3 q(0.3, 0.7, 0.2);
  const BuiltinOptions o = BuiltinOptions{4, 2, 8 * kBlockCells + 3 * kSplitCost};
  const std::vector<Block> leaves = refineBlocks(o, "test", [&](const BlockBox& box) {
    const glm::dvec3 d = glm::max(glm::max(box.lower - q, q - box.upper), glm::dvec3(0.0));
    return -glm::length(d);
  });
  ASSERT_EQ(cellCount(leaves), o.targetCells);
  const WorldTransform transform = generatorTransform(o);
  int containing = 0;
  for (const Block& b : leaves) {
    const BlockBox box = blockBox(b, transform);
    if (glm::all(glm::lessThanEqual(box.lower, q)) && glm::all(glm::lessThan(q, box.upper))) {
      ++containing;
      EXPECT_EQ(b.level, 0);
    }
  }
  EXPECT_EQ(containing, 1);
}

TEST(BlockRefiner, LevelZeroBlocksAreNeverSplit) {
  const BuiltinOptions uniform = BuiltinOptions{1, 3, 1'000'000};
  std::vector<Block> leaves = refineBlocks(uniform, "test", hashedPriority);
  EXPECT_EQ(cellCount(leaves), rootCells(uniform));

  const BuiltinOptions twoLevels = BuiltinOptions{2, 2, 1'000'000};
  leaves = refineBlocks(twoLevels, "test", hashedPriority);
  EXPECT_EQ(cellCount(leaves), 8 * rootCells(twoLevels));
  for (const Block& b : leaves) EXPECT_EQ(b.level, 0);
}

TEST(BlockRefiner, StaysWithinTheBudgetUsesItAndTilesTheDomain) {
  for (const BuiltinOptions& o :
       {BuiltinOptions{4, 2, 20'000}, BuiltinOptions{5, 1, 30'000}, BuiltinOptions{3, 3, 50'000},
        BuiltinOptions{6, 1, 100'000}, BuiltinOptions{2, 2, 7'000}}) {
    const std::vector<Block> leaves = refineBlocks(o, "test", hashedPriority);
    const std::size_t cells = cellCount(leaves);
    EXPECT_LE(cells, o.targetCells);
    const bool allFinest =
        std::all_of(leaves.begin(), leaves.end(), [](const Block& b) { return b.level == 0; });
    if (!allFinest) {
      EXPECT_GT(cells + kSplitCost, o.targetCells) << "budget left unused";
    }

    // Volumes add up to the domain, and AmrField rejects overlaps: the leaves tile it exactly.
    const std::int64_t extent = std::int64_t(o.rootBlocks) * kBlockSide << (o.levels - 1);
    std::int64_t volume = 0;
    for (const Block& b : leaves) {
      EXPECT_GE(b.level, 0);
      EXPECT_LT(b.level, o.levels);
      volume += std::int64_t(b.span()) * b.span() * b.span();
    }
    EXPECT_EQ(volume, extent * extent * extent);
    const bricks::AmrField field = emitCells(
        leaves, generatorTransform(o), {}, [](auto&&...) {}, "test");
    EXPECT_EQ(field.bounds().lower, glm::ivec3(0));
    EXPECT_EQ(field.bounds().upper, glm::ivec3(int(extent)));
    EXPECT_DOUBLE_EQ(field.transform().spacing.x * double(extent), 1.0);
  }
}

TEST(BlockRefiner, ValidatesTheOptions) {
  const auto rejects = [](const BuiltinOptions& o, const std::string& word) {
    try {
      refineBlocks(o, "builtin:test", hashedPriority);
      ADD_FAILURE() << "accepted options naming " << word;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
      EXPECT_EQ(e.source(), "builtin:test");
    }
  };
  rejects(BuiltinOptions{0, 2, 100'000}, "levels");
  rejects(BuiltinOptions{9, 2, 100'000}, "levels");
  rejects(BuiltinOptions{-1, 2, 100'000}, "levels");
  rejects(BuiltinOptions{3, 0, 100'000}, "rootBlocks");
  rejects(BuiltinOptions{3, -2, 100'000}, "rootBlocks");
  rejects(BuiltinOptions{8, (1 << 20) + 1, std::size_t(1) << 60},
          "rootBlocks");  // over 2^30 finest cells per axis
  rejects(BuiltinOptions{3, 2048, std::size_t(1) << 60}, "rootBlocks");  // 4.4e12 root cells
  rejects(BuiltinOptions{3, 2, 8 * kBlockCells - 1}, "targetCells");
  EXPECT_NO_THROW(refineBlocks(BuiltinOptions{8, 1, kBlockCells}, "test", hashedPriority));
  EXPECT_NO_THROW(refineBlocks(BuiltinOptions{1, 1, kBlockCells}, "test", hashedPriority));
}

}  // namespace
}  // namespace amrstream::synth
