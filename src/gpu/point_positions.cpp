#include "point_positions.hpp"

#include "flow/cell_point.hpp"
#include "flow/precise_position.hpp"

namespace amrstream::gpu {

void toPhysicalPositions(const flow::VectorVolume& volume, const glm::vec3* cells,
                         const std::int32_t* ids, std::size_t count, glm::vec3* high,
                         glm::vec3* low) {
  const WorldTransform& transform = volume.transform;
  const std::vector<shared::Region>& regions = volume.regions.regions;
  for (std::size_t i = 0; i < count; ++i) {
    if (ids) {
      const glm::ivec3 corner = ids[i] >= 0 && std::size_t(ids[i]) < regions.size()
                                    ? flow::regionCorner(regions[std::size_t(ids[i])].lower)
                                    : glm::ivec3(0);
      const flow::SplitPosition split =
          flow::splitPosition(transform.toPhysical(glm::dvec3(corner) + glm::dvec3(cells[i])));
      high[i] = split.high;
      low[i] = split.low;
    } else {
      high[i] = glm::vec3(transform.toPhysical(glm::dvec3(cells[i])));
    }
  }
}

}  // namespace amrstream::gpu
