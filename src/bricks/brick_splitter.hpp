#pragma once
// Private to the brick builder: the recursive kd split of one level's cells into boxes of cells
// with no holes (docs/architecture.md, "Bricks").

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace amrstream::bricks::detail {

// A cell of one level, in that level's integer grid (lower corner >> level).
struct GridCell {
  glm::ivec3 g;
  std::uint32_t cellId;
};

// A full box of cells: after splitting, its size.x * size.y * size.z cells are
// cells[begin, begin + volume), in no particular order.
struct GridBox {
  glm::ivec3 lower;  // level-grid coordinates
  glm::ivec3 size;
  std::uint32_t begin;
};

// Reorders `cells` (all of one level, no duplicates) so that every output box owns a contiguous
// range, and returns the boxes sorted by begin. Box sides are at most maxSide. Parallel; the
// result depends only on the input order, not on thread scheduling.
std::vector<GridBox> splitIntoBoxes(std::span<GridCell> cells, int maxSide);

}  // namespace amrstream::bricks::detail
