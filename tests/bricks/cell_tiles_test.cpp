// The brick builder's first pass: a field's cells grouped by level and aligned tile. Every cell
// must land once, in the group of its level and tile, in groups ordered by level then tile,
// whatever the tiles' number forces on their side.

#include "bricks/cell_tiles.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "oracles.hpp"

namespace amrstream::testing {
namespace {

using bricks::detail::groupIntoTiles;
using bricks::detail::TiledCells;

// Two levels over a box whose lower corner is negative and not a multiple of any tile side:
// level-1 cells in a 20^3 block, level-0 cells in a 24^3 block beside it, listed shuffled.
bricks::AmrField twoLevelsShuffled() {
  const glm::ivec3 origin(-37, 5, -3);
  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
  for (int z = 0; z < 20; ++z)
    for (int y = 0; y < 20; ++y)
      for (int x = 0; x < 20; ++x) {
        lowers.push_back(2 * glm::ivec3(x, y, z) + glm::ivec3(-38, 4, -4));
        levels.push_back(1);
      }
  for (int z = 0; z < 24; ++z)
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 24; ++x) {
        lowers.push_back(origin + glm::ivec3(x + 40, y, z));
        levels.push_back(0);
      }
  std::vector<std::size_t> order(lowers.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(9));
  std::vector<glm::ivec3> shuffledLowers;
  std::vector<std::uint8_t> shuffledLevels;
  for (const std::size_t i : order) {
    shuffledLowers.push_back(lowers[i]);
    shuffledLevels.push_back(levels[i]);
  }
  return makeField(shuffledLowers, shuffledLevels);
}

// The tile side a group's cells share: the smallest power of two >= minSide whose tiles from the
// field's lower corner hold all of them in one.
int sharedTileSide(const bricks::AmrField& field, const TiledCells& tiled,
                   const TiledCells::Group& group, int minSide) {
  const glm::ivec3 origin = field.bounds().lower >> group.level;
  for (int side = minSide;; side *= 2) {
    const glm::ivec3 first = (tiled.cells[group.begin].g - origin) / side;
    bool same = true;
    for (std::size_t i = group.begin; i < group.end && same; ++i)
      same = (tiled.cells[i].g - origin) / side == first;
    if (same) return side;
  }
}

void expectEveryCellOnceInItsLevel(const bricks::AmrField& field, const TiledCells& tiled) {
  ASSERT_EQ(tiled.count, field.cellCount());
  std::vector<int> seen(field.cellCount(), 0);
  std::size_t next = 0;
  int level = 0;
  for (const TiledCells::Group& group : tiled.groups) {
    EXPECT_EQ(group.begin, next);
    EXPECT_LT(group.begin, group.end);
    EXPECT_GE(group.level, level);
    level = group.level;
    next = group.end;
    for (std::size_t i = group.begin; i < group.end; ++i) {
      const std::uint32_t id = tiled.cells[i].cellId;
      ++seen[id];
      EXPECT_EQ(field.levels()[id], group.level);
      EXPECT_EQ(tiled.cells[i].g, field.lowers()[id] >> group.level);
    }
  }
  EXPECT_EQ(next, field.cellCount());
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

TEST(CellTiles, EachTileOfEachLevelIsOneGroup) {
  const bricks::AmrField field = twoLevelsShuffled();
  const TiledCells tiled = groupIntoTiles(field, 8, std::size_t(1) << 20);
  expectEveryCellOnceInItsLevel(field, tiled);
  // Tiles of 8 from the field's lower corner (-38, 4, -4): the level-1 block's 20 cells an axis
  // from 0 of its tiles' grid cover 3 tiles an axis; the level-0 block's 24 from 41, 1, 1 cover 4.
  std::size_t groups[2] = {0, 0};
  for (const TiledCells::Group& group : tiled.groups) {
    ++groups[group.level];
    EXPECT_EQ(sharedTileSide(field, tiled, group, 8), 8);
  }
  EXPECT_EQ(groups[1], 27u);
  EXPECT_EQ(groups[0], 64u);
}

TEST(CellTiles, TooManyTilesMakeLargerTiles) {
  const bricks::AmrField field = twoLevelsShuffled();
  // Tiles of 8 over the finest level's grid, 65 x 40 x 40 cells from the field's lower corner,
  // number 9 x 5 x 5 (over 40), and of 16 5 x 3 x 3: its tiles are 32 wide, 3 x 2 x 2. The
  // level-1 grid, 33 x 20 x 20, takes tiles of 16: 3 x 2 x 2.
  const TiledCells tiled = groupIntoTiles(field, 8, 40);
  expectEveryCellOnceInItsLevel(field, tiled);
  const int sides[2] = {32, 16};
  std::size_t groups[2] = {0, 0};
  for (const TiledCells::Group& group : tiled.groups) {
    ++groups[group.level];
    EXPECT_LE(sharedTileSide(field, tiled, group, 8), sides[group.level]);
  }
  // The level-0 block spans x 41..64 of its grid: tiles 1 and 2 of 32. The level-1 block's
  // 20 x 20 x 20 cells from 0 make 2 tiles of 16 an axis.
  EXPECT_EQ(groups[0], 2u);
  EXPECT_EQ(groups[1], 8u);
}

// Two cells at opposite corners of a box 2^30 finest cells wide: 2^23 tiles of 128 an axis, whose
// count overflows 64 bits, are too many.
TEST(CellTiles, TheWidestBoxGroupsItsCellsApart) {
  const int half = 1 << 29;
  const bricks::AmrField field = makeField({glm::ivec3(-half), glm::ivec3(half - 1)}, {0, 0});
  const TiledCells tiled = groupIntoTiles(field, 128, std::size_t(1) << 22);
  expectEveryCellOnceInItsLevel(field, tiled);
  EXPECT_EQ(tiled.groups.size(), 2u);
}

}  // namespace
}  // namespace amrstream::testing
