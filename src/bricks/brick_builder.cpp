#include "brick_builder.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>
#include <string>

#include "brick_splitter.hpp"
#include "cell_tiles.hpp"
#include "util/huge_pages.hpp"

namespace amrstream::bricks {

namespace {
// At most this many tiles (8 bytes each) group a field's cells, whatever its extent.
constexpr std::size_t kMaxTiles = std::size_t(1) << 22;
}  // namespace

std::vector<float> BrickSet::gather(const Channel& channel) const {
  if (channel.values.size() != cellIds.size())
    throw std::invalid_argument("gather: channel '" + channel.name + "' has " +
                                std::to_string(channel.values.size()) + " values for " +
                                std::to_string(cellIds.size()) + " cells");
  std::vector<float> out(cellIds.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cellIds.size()), [&](const auto& range) {
    for (std::size_t slot = range.begin(); slot != range.end(); ++slot)
      out[slot] = channel.values[cellIds[slot]];
  });
  return out;
}

BrickSet buildBricks(const AmrField& field, const BrickBuildOptions& options) {
  if (options.maxBrickSide < 1)
    throw std::invalid_argument("maxBrickSide must be at least 1, got " +
                                std::to_string(options.maxBrickSide));
  if (field.cellCount() > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("buildBricks supports at most 2^32 - 1 cells, got " +
                                std::to_string(field.cellCount()));

  // Tiles of four times the cap keep nearly every brick the whole level's split would make,
  // while each tile's cells are split from the caches, not from memory.
  const int tileSide = 4 * int(std::bit_floor(unsigned(std::min(options.maxBrickSide, 1 << 27))));
  detail::TiledCells sorted = detail::groupIntoTiles(field, tileSide, kMaxTiles);
  std::vector<std::vector<detail::GridBox>> boxes(sorted.groups.size());
  tbb::parallel_for(std::size_t(0), sorted.groups.size(), [&](std::size_t g) {
    const detail::TiledCells::Group& group = sorted.groups[g];
    boxes[g] = detail::splitIntoBoxes(
        std::span(sorted.cells.get() + group.begin, group.end - group.begin), options.maxBrickSide);
  });

  // Boxes hold exactly their cells, so the cells' position in `sorted` is the brick's slot range.
  BrickSet set;
  for (std::size_t g = 0; g < sorted.groups.size(); ++g) {
    const detail::TiledCells::Group& group = sorted.groups[g];
    const int width = AmrField::cellWidth(group.level);
    for (const detail::GridBox& box : boxes[g])
      set.bricks.push_back(
          {box.lower * width, group.level, box.size, std::uint32_t(group.begin + box.begin)});
  }
  resizeInHugePages(set.cellIds, sorted.count);
  tbb::parallel_for(std::size_t(0), set.bricks.size(), [&](std::size_t b) {
    const shared::Brick& brick = set.bricks[b];
    const glm::ivec3 lower = brick.lower >> brick.level;
    const std::size_t count = std::size_t(brick.size.x) * brick.size.y * brick.size.z;
    for (std::size_t i = brick.valueOffset; i < brick.valueOffset + count; ++i) {
      const glm::ivec3 local = sorted.cells[i].g - lower;
      const std::size_t slot =
          std::size_t(local.x) +
          std::size_t(brick.size.x) * (std::size_t(local.y) + std::size_t(brick.size.y) * local.z);
      set.cellIds[brick.valueOffset + slot] = sorted.cells[i].cellId;
    }
  });
  return set;
}

CellBox brickDomainDoubled(const shared::Brick& brick) {
  const int width = AmrField::cellWidth(brick.level);
  return {2 * brick.lower - width, 2 * (brick.lower + brick.size * width) + width};
}

}  // namespace amrstream::bricks
