#include "cell_tiles.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cstdint>

#include "util/huge_pages.hpp"

namespace amrstream::bricks::detail {

namespace {

// One level's tiles over the field's bounds: tile t of a level-grid cell g is
// (g - origin) >> shift.
struct LevelTiles {
  int shift = 0;
  glm::ivec3 origin{0};
  glm::ivec3 count{1};
  std::size_t first = 0;  // the key of its tile (0, 0, 0)

  std::size_t tiles() const { return std::size_t(count.x) * std::size_t(count.y) * count.z; }
  std::size_t key(glm::ivec3 g) const {
    const glm::ivec3 t = (g - origin) >> shift;
    return first + std::size_t(t.x) +
           std::size_t(count.x) * (std::size_t(t.y) + std::size_t(count.y) * std::size_t(t.z));
  }
};

std::vector<LevelTiles> tilesOfLevels(const AmrField& field, int tileSide, std::size_t maxTiles) {
  const CellBox bounds = field.bounds();
  std::vector<LevelTiles> levels(std::size_t(field.coarsestLevel()) + 1);
  std::size_t keys = 0;
  for (std::size_t level = 0; level < levels.size(); ++level) {
    // The tiles start at the field's lower corner (AMR codes align their blocks to the domain's
    // corner, not to zero).
    LevelTiles& tiles = levels[level];
    tiles.origin = bounds.lower >> int(level);
    const glm::ivec3 last = ((bounds.upper - 1) >> int(level)) - tiles.origin;
    for (tiles.shift = std::countr_zero(unsigned(tileSide));; ++tiles.shift) {
      tiles.count = (last >> tiles.shift) + 1;
      // In doubles: up to 2^30 tiles an axis overflow 64 bits.
      const double count = double(tiles.count.x) * double(tiles.count.y) * double(tiles.count.z);
      if (count <= double(maxTiles) || count == 1) break;
    }
    tiles.first = keys;
    keys += tiles.tiles();
  }
  return levels;
}

// Calls run(key, first, last) for each run of consecutive cells of [begin, end) in one tile.
template <typename Run>
void eachRun(const AmrField& field, const std::vector<LevelTiles>& levels, std::size_t begin,
             std::size_t end, Run run) {
  const auto lowers = field.lowers();
  const auto cellLevels = field.levels();
  std::size_t runKey = 0, runBegin = begin;
  for (std::size_t i = begin; i < end; ++i) {
    const int level = cellLevels[i];
    const std::size_t key = levels[level].key(lowers[i] >> level);
    if (i == begin) {
      runKey = key;
    } else if (key != runKey) {
      run(runKey, runBegin, i);
      runKey = key;
      runBegin = i;
    }
  }
  if (end > begin) run(runKey, runBegin, end);
}

}  // namespace

TiledCells groupIntoTiles(const AmrField& field, int tileSide, std::size_t maxTiles) {
  constexpr std::size_t kBlock = std::size_t(1) << 14;
  const std::size_t n = field.cellCount();
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  const std::vector<LevelTiles> levels = tilesOfLevels(field, tileSide, maxTiles);
  const std::size_t keys = levels.back().first + levels.back().tiles();

  // Counts per tile, then each tile's next free slot. Runs of cells in one tile (an AMR block's
  // cells are listed together) take one atomic add each.
  std::vector<std::uint64_t> slots(keys, 0);
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
    eachRun(field, levels, block * kBlock, std::min(n, (block + 1) * kBlock),
            [&](std::size_t key, std::size_t first, std::size_t last) {
              std::atomic_ref(slots[key]).fetch_add(last - first, std::memory_order_relaxed);
            });
  });

  TiledCells out{std::make_unique_for_overwrite<GridCell[]>(n), n, {}};
  adviseHugePages(out.cells.get(), n * sizeof(GridCell));
  std::size_t next = 0;
  for (std::size_t level = 0; level < levels.size(); ++level)
    for (std::size_t key = levels[level].first; key < levels[level].first + levels[level].tiles();
         ++key) {
      const std::size_t count = slots[key];
      slots[key] = next;
      if (count > 0) out.groups.push_back({next, next + count, int(level)});
      next += count;
    }

  const auto lowers = field.lowers();
  const auto cellLevels = field.levels();
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t block) {
    eachRun(field, levels, block * kBlock, std::min(n, (block + 1) * kBlock),
            [&](std::size_t key, std::size_t first, std::size_t last) {
              std::size_t at =
                  std::atomic_ref(slots[key]).fetch_add(last - first, std::memory_order_relaxed);
              for (std::size_t i = first; i < last; ++i)
                // Cells are aligned to their level, so the arithmetic shift is an exact division.
                out.cells[at++] = {lowers[i] >> int(cellLevels[i]), std::uint32_t(i)};
            });
  });
  return out;
}

}  // namespace amrstream::bricks::detail
