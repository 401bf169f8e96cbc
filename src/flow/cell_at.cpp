#include "cell_at.hpp"

#include "sampler.hpp"

namespace amrstream::flow {

std::optional<CellAt> cellAt(const VectorVolume& volume, glm::dvec3 q) {
  const std::int32_t region = locateRegion(volume, toCellPoint(q));
  if (region < 0) return std::nullopt;
  const shared::Region& r = volume.regions.regions[std::size_t(region)];
  for (std::uint32_t k = 0; k < r.brickCount; ++k) {
    const std::uint32_t b = volume.regions.regionBricks[r.brickOffset + k];
    if (b >= volume.originalBrickCount) continue;
    const shared::Brick& brick = volume.bricks[b];
    const double width = double(1 << brick.level);
    const glm::dvec3 local = (q - glm::dvec3(brick.lower)) / width;
    if (glm::any(glm::lessThan(local, glm::dvec3(0.0))) ||
        glm::any(glm::greaterThanEqual(local, glm::dvec3(brick.size))))
      continue;
    const glm::ivec3 cell(glm::floor(local));
    const std::uint32_t slot =
        brick.valueOffset + std::uint32_t(cell.x + brick.size.x * (cell.y + brick.size.y * cell.z));
    return CellAt{slot, glm::dvec3(brick.lower) + (glm::dvec3(cell) + 0.5) * width, width};
  }
  return std::nullopt;
}

}  // namespace amrstream::flow
