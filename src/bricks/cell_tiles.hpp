#pragma once
// Private to the brick builder: a field's cells grouped by level and, within a level, by aligned
// tiles of that level's grid, so that each tile's cells are split into bricks on their own, from
// the caches rather than from memory (docs/architecture.md, "Bricks").

#include <cstddef>
#include <memory>
#include <vector>

#include "amr_field.hpp"
#include "brick_splitter.hpp"

namespace amrstream::bricks::detail {

struct TiledCells {
  // The cells of one tile: cells[begin, end), all of `level`.
  struct Group {
    std::size_t begin = 0, end = 0;
    int level = 0;
  };

  std::unique_ptr<GridCell[]> cells;
  std::size_t count = 0;
  // The non-empty tiles by level (finest first), then by tile (x fastest). Within a tile the
  // cells' order depends on the threads' scheduling.
  std::vector<Group> groups;
};

// Tiles are cubes of `tileSide` cells of their level (a power of two) from the field's lower
// corner, or of a larger power of two for a level whose tiles over the field's bounds would number
// more than `maxTiles`.
TiledCells groupIntoTiles(const AmrField& field, int tileSide, std::size_t maxTiles);

}  // namespace amrstream::bricks::detail
