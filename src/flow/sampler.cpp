#include "sampler.hpp"

#include <cmath>
#include <limits>
#include <span>

namespace amrstream::flow {

namespace {

// Whether lattice point k lies in the domain: [2 lower, 2 upper) on the lattice.
bool insideDomain(const VectorVolume& volume, glm::ivec3 k) {
  return glm::all(glm::greaterThanEqual(k, 2 * volume.domain.lower)) &&
         glm::all(glm::lessThan(k, 2 * volume.domain.upper));
}

bool insideBox(const shared::Region& region, glm::ivec3 k) {
  return glm::all(glm::greaterThanEqual(k, region.lower)) &&
         glm::all(glm::lessThan(k, region.upper));
}

// The 2x2x2 cells of one brick around p with a non-zero tent weight
// H_i(p) = prod_d max(0, 1 - |c_i,d - p_d| / w_i): calls
// visit(slot, axisWeights, offset, width, p - c_i) for each such cell inside the brick, in the
// order every reconstruction sums them.
template <typename Visit>
void forEachTentCell(const shared::Brick& brick, const CellPoint& p, Visit&& visit) {
  const float width = float(1 << brick.level);
  const glm::vec3 local = (glm::vec3(p.anchor - brick.lower) + p.offset) / width - 0.5f;
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
    const std::uint32_t slot =
        brick.valueOffset + std::uint32_t(cell.x + brick.size.x * (cell.y + brick.size.y * cell.z));
    visit(slot, axisWeight, offset, width, width * (frac - glm::vec3(offset)));
  }
}

template <typename Visit>
void forEachRegionTentCell(const VectorVolume& volume, const shared::Region& region,
                           const CellPoint& p, Visit&& visit) {
  for (std::uint32_t k = 0; k < region.brickCount; ++k)
    forEachTentCell(volume.bricks[volume.regions.regionBricks[region.brickOffset + k]], p, visit);
}

// The tent basis-function sum over the region's bricks: returns the sum of the weights and sets
// `weighted` to the weighted sum of the brick-ordered `values`. The weights are computed once per
// cell and applied to all components.
template <typename Value>
float reconstruct(const VectorVolume& volume, const shared::Region& region, const CellPoint& p,
                  std::span<const Value> values, Value& weighted) {
  float weightSum = 0.0f;
  weighted = Value(0.0f);
  forEachRegionTentCell(
      volume, region, p,
      [&](std::uint32_t slot, glm::vec3 axisWeight, glm::ivec3, float, glm::vec3) {
        const float weight = axisWeight.x * axisWeight.y * axisWeight.z;
        weightSum += weight;
        weighted += weight * values[slot];
      });
  return weightSum;
}

// The linear interpolant: the same weights over each cell's linear model v_i + G_i (p - c_i).
float reconstructLinear(const VectorVolume& volume, const shared::Region& region,
                        const CellPoint& p, glm::vec3& weighted) {
  float weightSum = 0.0f;
  weighted = glm::vec3(0.0f);
  forEachRegionTentCell(
      volume, region, p,
      [&](std::uint32_t slot, glm::vec3 axisWeight, glm::ivec3, float, glm::vec3 toP) {
        const float weight = axisWeight.x * axisWeight.y * axisWeight.z;
        const glm::vec3* g = &volume.vectorGradients[3 * slot];
        weightSum += weight;
        weighted +=
            weight * (volume.values[slot] +
                      glm::vec3(glm::dot(g[0], toP), glm::dot(g[1], toP), glm::dot(g[2], toP)));
      });
  return weightSum;
}

// The region containing p, trying the cache's region first; -1 outside the domain and regions.
std::int32_t findRegion(const VectorVolume& volume, const CellPoint& p, RegionCache* cache) {
  if (!isNear(p)) return -1;
  const glm::ivec3 k = latticeOf(p);
  if (!insideDomain(volume, k)) return -1;
  std::int32_t regionId = cache ? cache->id : -1;
  if (regionId < 0 || !insideBox(volume.regions.regions[regionId], k)) {
    regionId = volume.regions.locate(k);
    if (regionId >= 0 && cache) cache->id = regionId;
  }
  return regionId;
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

}  // namespace

CellPoint wrapPeriodic(const VectorVolume& volume, CellPoint p) {
  if (!isNear(p)) return p;
  const glm::ivec3 cell = cellOf(p);
  for (int a = 0; a < 3; ++a) {
    if (!volume.periodic[a]) continue;
    const int lower = volume.domain.lower[a], upper = volume.domain.upper[a];
    if (cell[a] >= upper)
      p.anchor[a] -= upper - lower;
    else if (cell[a] < lower)
      p.anchor[a] += upper - lower;
  }
  return p;
}

std::int32_t locateRegion(const VectorVolume& volume, const CellPoint& p) {
  return findRegion(volume, p, nullptr);
}

VectorSample sampleVector(const VectorVolume& volume, const CellPoint& p, RegionCache* cache) {
  VectorSample sample;
  const std::int32_t regionId = findRegion(volume, p, cache);
  if (regionId < 0) return sample;
  const shared::Region& region = volume.regions.regions[regionId];
  sample.located = true;
  sample.cellWidth = region.finestCellWidth;
  sample.region = regionId;

  glm::vec3 weighted(0.0f);
  const float weightSum =
      volume.interpolant == Interpolant::Linear
          ? reconstructLinear(volume, region, p, weighted)
          : reconstruct(volume, region, p, std::span<const glm::vec3>(volume.values), weighted);
  if (!(weightSum > kMinWeightSum)) return sample;
  sample.value = weighted / weightSum;
  sample.valid = !glm::any(glm::isnan(sample.value)) && !glm::any(glm::isinf(sample.value));
  return sample;
}

std::optional<float> sampleScalar(const VectorVolume& volume, std::span<const float> scalars,
                                  const CellPoint& p, RegionCache* cache,
                                  std::span<const glm::vec3> gradients) {
  const std::int32_t regionId = findRegion(volume, p, cache);
  if (regionId < 0) return std::nullopt;
  float weightSum = 0.0f, weighted = 0.0f;
  forEachRegionTentCell(
      volume, volume.regions.regions[regionId], p,
      [&](std::uint32_t slot, glm::vec3 axisWeight, glm::ivec3, float, glm::vec3 toP) {
        const float weight = axisWeight.x * axisWeight.y * axisWeight.z;
        weightSum += weight;
        weighted += weight * (gradients.empty() ? scalars[slot]
                                                : scalars[slot] + glm::dot(gradients[slot], toP));
      });
  if (!(weightSum > kMinWeightSum)) return std::nullopt;
  const float value = weighted / weightSum;
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

void sampleChannels(const VectorVolume& volume, std::int32_t region, const CellPoint& p,
                    std::span<float> out) {
  const std::size_t channels = out.size();
  if (channels == 0) return;
  std::fill(out.begin(), out.end(), 0.0f);
  float weightSum = 0.0f;
  if (region >= 0)
    forEachRegionTentCell(
        volume, volume.regions.regions[region], p,
        [&](std::uint32_t slot, glm::vec3 axisWeight, glm::ivec3, float, glm::vec3 toP) {
          const float weight = axisWeight.x * axisWeight.y * axisWeight.z;
          weightSum += weight;
          const float* values = volume.channelValues.data() + slot * channels;
          for (std::size_t c = 0; c < channels; ++c) out[c] += weight * values[c];
          if (volume.interpolant != Interpolant::Linear) return;
          const glm::vec3* g = volume.channelGradients.data() + slot * channels;
          for (std::size_t c = 0; c < channels; ++c) out[c] += weight * glm::dot(g[c], toP);
        });
  for (float& value : out) value = weightSum > kMinWeightSum ? value / weightSum : kNaN;
}

glm::vec3 sampleVorticity(const VectorVolume& volume, std::int32_t region, const CellPoint& p) {
  if (region < 0) return glm::vec3(kNaN);
  const bool linear = volume.interpolant == Interpolant::Linear;
  float weightSum = 0.0f;
  glm::vec3 weighted(0.0f), weightGradient(0.0f);
  glm::vec3 weightedGradient[3] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
  glm::vec3 weightedModelGradient[3] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
  forEachRegionTentCell(
      volume, volume.regions.regions[region], p,
      [&](std::uint32_t slot, glm::vec3 a, glm::ivec3 offset, float width, glm::vec3 toP) {
        const glm::vec3 da = (2.0f * glm::vec3(offset) - 1.0f) / width;
        const float weight = a.x * a.y * a.z;
        const glm::vec3 gradient(da.x * a.y * a.z, a.x * da.y * a.z, a.x * a.y * da.z);
        glm::vec3 v = volume.values[slot];
        if (linear) {  // the cell's model v_i + G_i (p - c_i), and its derivative G_i
          const glm::vec3* g = &volume.vectorGradients[3 * slot];
          v += glm::vec3(glm::dot(g[0], toP), glm::dot(g[1], toP), glm::dot(g[2], toP));
          for (int d = 0; d < 3; ++d)
            weightedModelGradient[d] += weight * glm::vec3(g[0][d], g[1][d], g[2][d]);
        }
        weightSum += weight;
        weighted += weight * v;
        weightGradient += gradient;
        for (int d = 0; d < 3; ++d) weightedGradient[d] += gradient[d] * v;
      });
  if (!(weightSum > kMinWeightSum)) return glm::vec3(kNaN);
  const glm::vec3 value = weighted / weightSum;
  const glm::vec3 cellsPerPhysical(1.0 / volume.transform.spacing);
  glm::vec3 jacobian[3];  // jacobian[d] = dB/dx_d, physical
  for (int d = 0; d < 3; ++d)
    jacobian[d] = (weightedGradient[d] - value * weightGradient[d] + weightedModelGradient[d]) /
                  weightSum * cellsPerPhysical[d];
  return {jacobian[1].z - jacobian[2].y, jacobian[2].x - jacobian[0].z,
          jacobian[0].y - jacobian[1].x};
}

}  // namespace amrstream::flow
