#include "bricks/descent_tree.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <random>

#include "deep_nest.hpp"
#include "flow/cell_point.hpp"
#include "flow/vector_volume.hpp"
#include "oracles.hpp"
#include "random_amr.hpp"

namespace amrstream::testing {
namespace {

using bricks::buildBricks;
using bricks::buildDescentTree;
using bricks::buildRegions;
using bricks::DescentTree;
using bricks::RegionSet;

// The leaf a descent from the root reaches, with no root box test: what the kernels did before
// the grid, and what they must still find.
std::int32_t descendFromRoot(const RegionSet& regions, glm::ivec3 k) {
  std::uint32_t index = 0;
  while (regions.tree[index].axis != AMRSTREAM_TREE_LEAF) {
    const shared::RegionTreeNode& node = regions.tree[index];
    index = k[int(node.axis)] < node.split ? node.child : node.child + 1;
  }
  const std::uint32_t leaf = regions.tree[index].child;
  return leaf == AMRSTREAM_NO_REGION ? -1 : std::int32_t(leaf);
}

// Lattice points: the probe points (where the oracle's doubled coordinates fit 32 bits), the
// lattice points around every region corner, random points in and around the root box, points
// far outside it on any axis, and the ends of the 32-bit range.
std::vector<glm::ivec3> latticeProbes(const std::vector<shared::Brick>& bricks,
                                      const RegionSet& regions, std::uint64_t seed) {
  std::vector<glm::ivec3> out;
  const auto fits = [](glm::ivec3 k) {
    return glm::all(glm::lessThan(glm::abs(k), glm::ivec3(1 << 29)));
  };
  if (fits(regions.lower) && fits(regions.upper))
    for (const glm::vec3 p : probePoints(bricks, regions, seed, 400)) {
      const flow::CellPoint point(p);
      if (flow::isNear(point)) out.push_back(flow::latticeOf(point));
    }
  const auto clamped = [](glm::i64vec3 k) {
    return glm::ivec3(glm::clamp(k, glm::i64vec3(INT_MIN), glm::i64vec3(INT_MAX)));
  };
  for (const shared::Region& r : regions.regions)
    for (const glm::ivec3 corner : {r.lower, r.upper})
      for (int d = -1; d <= 0; ++d) out.push_back(clamped(glm::i64vec3(corner) + std::int64_t(d)));
  std::mt19937_64 random(seed);
  for (int i = 0; i < 400; ++i) {
    glm::i64vec3 k;
    for (int a = 0; a < 3; ++a)
      k[a] = std::uniform_int_distribution<std::int64_t>(
          std::int64_t(regions.lower[a]) - 4, std::int64_t(regions.upper[a]) + 4)(random);
    out.push_back(clamped(k));
  }
  std::uniform_int_distribution<int> anywhere(INT_MIN, INT_MAX);
  std::uniform_int_distribution<int> axis(0, 2);
  for (int i = 0; i < 200; ++i) {
    glm::ivec3 k = out[std::size_t(i) % out.size()];
    k[axis(random)] = anywhere(random);
    out.push_back(k);
  }
  out.push_back(glm::ivec3(INT_MIN));
  out.push_back(glm::ivec3(INT_MAX));
  out.push_back(glm::ivec3(INT_MIN, INT_MAX, 0));
  return out;
}

::testing::AssertionResult sameLeaves(const RegionSet& regions, const DescentTree& tree,
                                      const std::vector<glm::ivec3>& points) {
  for (const glm::ivec3 k : points) {
    const std::int32_t expected = descendFromRoot(regions, k);
    if (tree.locate(k) != expected)
      return ::testing::AssertionFailure()
             << "k = (" << k.x << ", " << k.y << ", " << k.z << "): " << tree.locate(k)
             << ", from the root " << expected;
    const bool inside = glm::all(glm::greaterThanEqual(k, regions.lower)) &&
                        glm::all(glm::lessThan(k, regions.upper));
    if (inside && tree.locate(k) != regions.locate(k))
      return ::testing::AssertionFailure()
             << "k = (" << k.x << ", " << k.y << ", " << k.z << ") differs from RegionSet::locate";
  }
  return ::testing::AssertionSuccess();
}

// Start nodes that are not the root: the grid skips levels.
std::size_t cellsBelowTheRoot(const DescentTree& tree) {
  const shared::RegionTreeNode& root = tree.nodes[tree.grid.entryCount];
  std::size_t below = 0;
  for (std::uint32_t i = 0; i < tree.grid.entryCount; ++i)
    below += tree.nodes[i].child != root.child || tree.nodes[i].axis != root.axis ||
             tree.nodes[i].split != root.split;
  return below;
}

TEST(DescentTree, EndsInTheLeafOfADescentFromTheRoot) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
    for (int levels = 1; levels <= 5; ++levels) {
      const auto field = variedRandomLayout(seed, levels);
      const bricks::BrickSet set = buildBricks(field, {3});
      const RegionSet regions = buildRegions(set.bricks);
      const std::vector<glm::ivec3> points = latticeProbes(set.bricks, regions, seed * 10 + levels);
      for (const std::uint32_t maxCells : {1u, 8u, 100u, 4096u, bricks::kMaxDescentCells}) {
        SCOPED_TRACE(::testing::Message()
                     << "seed " << seed << " levels " << levels << " cells " << maxCells);
        const DescentTree tree = buildDescentTree(regions, maxCells);
        EXPECT_LE(
            tree.grid.entryCount,
            std::max<std::size_t>(1, std::min<std::size_t>(maxCells, 2 * regions.tree.size())));
        EXPECT_EQ(tree.nodes.size(), tree.grid.entryCount + regions.tree.size());
        EXPECT_TRUE(sameLeaves(regions, tree, points));
      }
    }
}

TEST(DescentTree, CellsStartBelowTheRoot) {
  const auto field = randomAmr(
      21,
      {.levels = 4, .rootCells = {5, 4, 5}, .refineProbability = 0.75, .origin = {-8, 16, -24}});
  const bricks::BrickSet set = buildBricks(field, {1});
  const RegionSet regions = buildRegions(set.bricks);
  const DescentTree tree = buildDescentTree(regions);
  EXPECT_GT(tree.grid.entryCount, 1000u);
  EXPECT_GT(cellsBelowTheRoot(tree), tree.grid.entryCount / 2);
  EXPECT_TRUE(sameLeaves(regions, tree, latticeProbes(set.bricks, regions, 5)));
}

TEST(DescentTree, LatticesThatFillThirtyTwoBits) {
  const auto field = powersOfTwoAlongTheAxes();
  const bricks::BrickSet set = buildBricks(field, {1});
  const RegionSet regions = buildRegions(set.bricks);
  for (const std::uint32_t maxCells : {1u, 64u, bricks::kMaxDescentCells})
    EXPECT_TRUE(sameLeaves(regions, buildDescentTree(regions, maxCells),
                           latticeProbes(set.bricks, regions, 6)));
  // Two bricks 2^31 lattice units apart: the root box spans nearly the whole 32-bit range.
  const std::vector<shared::Brick> apart{{{(1 << 30) - 2, 0, 0}, 0, {1, 1, 1}, 0},
                                         {{-(1 << 29), 0, 0}, 0, {1, 1, 1}, 1}};
  const RegionSet wide = buildRegions(apart);
  for (const std::uint32_t maxCells : {1u, 2u, 8u, bricks::kMaxDescentCells})
    EXPECT_TRUE(sameLeaves(wide, buildDescentTree(wide, maxCells), latticeProbes(apart, wide, 7)));
}

TEST(DescentTree, NestsThirtyLevelsDeep) {
  for (const DeepNest& nest : {deepNest(), deepOctreeNest()}) {
    const flow::VectorVolume volume =
        flow::buildVectorVolume(nest.field, flow::chooseVectorChannels(nest.field, ""));
    for (const std::uint32_t maxCells : {1u, 64u, bricks::kMaxDescentCells})
      EXPECT_TRUE(sameLeaves(volume.regions, buildDescentTree(volume.regions, maxCells),
                             latticeProbes(volume.bricks, volume.regions, 8)));
  }
}

TEST(DescentTree, NoBricksIsEmptySpace) {
  const RegionSet empty = buildRegions({});
  const DescentTree tree = buildDescentTree(empty);
  EXPECT_EQ(tree.grid.entryCount, 1u);
  EXPECT_EQ(tree.locate(glm::ivec3(0)), -1);
  EXPECT_EQ(tree.locate(glm::ivec3(INT_MIN)), -1);
  EXPECT_EQ(tree.bytes().size(),
            sizeof(shared::RegionTreeGrid) + tree.nodes.size() * sizeof(shared::RegionTreeNode));
  // A region set never built (VectorVolume's default) has no tree at all: still one empty cell.
  const DescentTree none = buildDescentTree(RegionSet{});
  EXPECT_EQ(none.grid.entryCount, 1u);
  EXPECT_EQ(none.nodes.size(), 1u);
  EXPECT_EQ(none.locate(glm::ivec3(5)), -1);
}

}  // namespace
}  // namespace amrstream::testing
