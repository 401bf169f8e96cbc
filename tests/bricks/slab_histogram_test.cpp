// The split plane of a node large enough that its histograms are summed over pieces of its cells
// in parallel: the slabs' counts and bounds must be those of the cells, in whatever order the
// cells come.

#include "bricks/slab_histogram.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace amrstream::bricks::detail {
namespace {

// 120 x 80 x 80 cells less the slabs x = 45 and x = 70; beyond x = 70 only y in [10, 50); the
// slabs x = 55, 60 and 65 hold one cell each, so a piece of the cells lost from the sum would
// likely leave a false gap nearer the centre. The empty slab nearest the centre (x = 60) is
// x = 70.
std::vector<GridCell> cellsWithTwoGaps() {
  std::vector<GridCell> cells;
  for (int z = 0; z < 80; ++z)
    for (int y = 0; y < 80; ++y)
      for (int x = 0; x < 120; ++x) {
        if (x == 45 || x == 70 || (x > 70 && (y < 10 || y >= 50))) continue;
        if ((x == 55 || x == 60 || x == 65) && (y != x || z != 7)) continue;
        cells.push_back(
            {glm::ivec3(x, y, z) + glm::ivec3(1000, -7, 3), std::uint32_t(cells.size())});
      }
  return cells;
}

TEST(SlabHistogram, ALargeNodeSplitsAtItsCentralGapWithTightSides) {
  std::vector<GridCell> cells = cellsWithTwoGaps();
  ASSERT_GT(cells.size(), std::size_t(1) << 19);  // summed in pieces
  std::shuffle(cells.begin(), cells.end(), std::mt19937(5));
  const glm::ivec3 offset(1000, -7, 3);
  const GridBounds bounds{offset, offset + glm::ivec3(120, 80, 80)};
  const HistogramSplit split = histogramSplit(cells, bounds, 4);
  EXPECT_EQ(split.plane.axis, 0);
  EXPECT_EQ(split.plane.at, offset.x + 70);
  EXPECT_EQ(split.lower, (GridBounds{offset, offset + glm::ivec3(70, 80, 80)}));
  EXPECT_EQ(split.upper,
            (GridBounds{offset + glm::ivec3(71, 10, 0), offset + glm::ivec3(120, 50, 80)}));
}

}  // namespace
}  // namespace amrstream::bricks::detail
