#include "sampler.hpp"

#include <cmath>
#include <span>

namespace amrstream::flow {

namespace {

bool insideDomain(const VectorVolume& volume, glm::vec3 p) {
  const glm::vec3 lower(volume.domain.lower), upper(volume.domain.upper);
  return glm::all(glm::greaterThanEqual(p, lower)) && glm::all(glm::lessThan(p, upper));
}

bool insideBox(const shared::Region& region, glm::vec3 p) {
  return glm::all(glm::greaterThanEqual(p, region.lower)) && glm::all(glm::lessThan(p, region.upper));
}

// The tent basis-function sum over the region's bricks: returns the sum of the weights and sets
// `weighted` to the weighted sum of the brick-ordered `values`. Only the 2x2x2 cells of each
// brick around p have a non-zero tent weight H_i(p) = prod_d max(0, 1 - |c_i,d - p_d| / w_i);
// the weights are computed once per brick and applied to all components.
template <typename Value>
float reconstruct(const VectorVolume& volume, const shared::Region& region, glm::vec3 p,
                  std::span<const Value> values, Value& weighted) {
  float weightSum = 0.0f;
  weighted = Value(0.0f);
  for (std::uint32_t k = 0; k < region.brickCount; ++k) {
    const shared::Brick& brick = volume.bricks[volume.regions.regionBricks[region.brickOffset + k]];
    const float width = float(1 << brick.level);
    const glm::vec3 local = (p - glm::vec3(brick.lower)) / width - 0.5f;
    const glm::vec3 base = glm::floor(local);
    const glm::vec3 frac = local - base;
    const glm::ivec3 lo(base);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::ivec3 offset(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      const glm::ivec3 cell = lo + offset;
      if (glm::any(glm::lessThan(cell, glm::ivec3(0))) ||
          glm::any(glm::greaterThanEqual(cell, brick.size)))
        continue;
      const glm::vec3 axisWeight = glm::mix(1.0f - frac, frac, glm::vec3(offset));
      const float weight = axisWeight.x * axisWeight.y * axisWeight.z;
      const std::uint32_t slot =
          brick.valueOffset +
          std::uint32_t(cell.x + brick.size.x * (cell.y + brick.size.y * cell.z));
      weightSum += weight;
      weighted += weight * values[slot];
    }
  }
  return weightSum;
}

// The region containing p, trying the cache's region first; -1 outside the domain and regions.
std::int32_t findRegion(const VectorVolume& volume, glm::vec3 p, RegionCache* cache) {
  if (!insideDomain(volume, p)) return -1;
  std::int32_t regionId = cache ? cache->id : -1;
  if (regionId < 0 || !insideBox(volume.regions.regions[regionId], p)) {
    regionId = volume.regions.locate(p);
    if (regionId >= 0 && cache) cache->id = regionId;
  }
  return regionId;
}

}  // namespace

std::int32_t locateRegion(const VectorVolume& volume, glm::vec3 p) {
  return insideDomain(volume, p) ? volume.regions.locate(p) : -1;
}

VectorSample sampleVector(const VectorVolume& volume, glm::vec3 p, RegionCache* cache) {
  VectorSample sample;
  const std::int32_t regionId = findRegion(volume, p, cache);
  if (regionId < 0) return sample;
  const shared::Region& region = volume.regions.regions[regionId];
  sample.located = true;
  sample.cellWidth = region.finestCellWidth;

  glm::vec3 weighted(0.0f);
  const float weightSum = reconstruct(volume, region, p, std::span<const glm::vec3>(volume.values), weighted);
  if (!(weightSum > kMinWeightSum)) return sample;
  sample.value = weighted / weightSum;
  sample.valid = !glm::any(glm::isnan(sample.value)) && !glm::any(glm::isinf(sample.value));
  return sample;
}

std::optional<float> sampleScalar(const VectorVolume& volume, std::span<const float> scalars,
                                  glm::vec3 p, RegionCache* cache) {
  const std::int32_t regionId = findRegion(volume, p, cache);
  if (regionId < 0) return std::nullopt;
  float weighted = 0.0f;
  const float weightSum =
      reconstruct(volume, volume.regions.regions[regionId], p, scalars, weighted);
  if (!(weightSum > kMinWeightSum)) return std::nullopt;
  const float value = weighted / weightSum;
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace amrstream::flow
