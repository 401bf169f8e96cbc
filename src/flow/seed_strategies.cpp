#include "seed_strategies.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "sampler.hpp"
#include "util/input_error.hpp"

namespace amrstream::flow {

namespace {

// 53 random bits -> [0, 1), the same on every standard library (see randomSeedsInBox).
double unitRandom(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

}  // namespace

SeedList seedsAlongLine(glm::dvec3 from, glm::dvec3 to, std::size_t count) {
  SeedList seeds;
  for (std::size_t i = 0; i < count; ++i) {
    const double t = count == 1 ? 0.5 : double(i) / double(count - 1);
    seeds.points.push_back(from + t * (to - from));
    seeds.origins.push_back(fmt::format("--seed-line point #{}", i));
  }
  return seeds;
}

SeedList seedsOnGrid(glm::dvec3 lower, glm::dvec3 upper, glm::ivec3 counts) {
  SeedList seeds;
  for (int k = 0; k < counts.z; ++k)
    for (int j = 0; j < counts.y; ++j)
      for (int i = 0; i < counts.x; ++i) {
        const glm::dvec3 t = (glm::dvec3(i, j, k) + 0.5) / glm::dvec3(counts);
        seeds.points.push_back(lower + t * (upper - lower));
        seeds.origins.push_back(fmt::format("--seed-grid point ({}, {}, {})", i, j, k));
      }
  return seeds;
}

bool insideACell(const VectorVolume& volume, glm::dvec3 cellUnits) {
  const std::int32_t region = locateRegion(volume, toCellPoint(cellUnits));
  if (region < 0) return false;
  const shared::Region& r = volume.regions.regions[std::size_t(region)];
  for (std::uint32_t i = 0; i < r.brickCount; ++i) {
    const shared::Brick& b = volume.bricks[volume.regions.regionBricks[r.brickOffset + i]];
    const glm::dvec3 lower(b.lower), upper = lower + glm::dvec3(b.size) * double(1 << b.level);
    if (glm::all(glm::greaterThanEqual(cellUnits, lower)) && glm::all(glm::lessThan(cellUnits, upper)))
      return true;
  }
  return false;
}

SeedList randomSeedsInCells(const VectorVolume& volume, glm::dvec3 lower, glm::dvec3 upper,
                            std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  SeedList seeds;
  const std::size_t maxDraws = 1000 * std::max<std::size_t>(count, 1);
  std::size_t draws = 0;
  while (seeds.points.size() < count) {
    if (draws == maxDraws)
      throw InputError("random seeds",
                       fmt::format("only {} of {} random points in the box ({:g}, {:g}, {:g}) .. "
                                   "({:g}, {:g}, {:g}) fell inside cells: the box is nearly all "
                                   "holes; give a --seed-box around the data or --seed-density",
                                   seeds.points.size(), draws, lower.x, lower.y, lower.z, upper.x,
                                   upper.y, upper.z));
    ++draws;
    const glm::dvec3 t(unitRandom(rng), unitRandom(rng), unitRandom(rng));
    const glm::dvec3 p = lower + t * (upper - lower);
    if (!insideACell(volume, volume.transform.toCellUnits(p))) continue;
    seeds.origins.push_back(fmt::format("random seed #{}", seeds.points.size()));
    seeds.points.push_back(p);
  }
  return seeds;
}

SeedList seedsInDensestCells(const bricks::AmrField& field, const DensestCellsOptions& options) {
  const bricks::Channel& channel = field.channel(options.channel);  // throws if absent
  if (!(options.percentile >= 0.0 && options.percentile <= 100.0))
    throw InputError("--seed-percentile",
                     fmt::format("{} is not a percentile in [0, 100]", options.percentile));

  // The value at the percentile (nearest rank), then every cell at or above it.
  std::vector<float> sorted = channel.values;
  const std::size_t rank =
      std::min(sorted.size() - 1,
               std::size_t(std::floor(options.percentile / 100.0 * double(sorted.size()))));
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(rank), sorted.end());
  const float threshold = sorted[rank];
  std::vector<std::uint32_t> candidates;
  for (std::size_t i = 0; i < channel.values.size(); ++i)
    if (channel.values[i] >= threshold) candidates.push_back(std::uint32_t(i));

  std::vector<double> cumulative;
  if (options.weighted) {
    cumulative.reserve(candidates.size());
    double sum = 0.0;
    for (std::uint32_t c : candidates) {
      if (!(channel.values[c] > 0.0f))
        throw InputError(field.source(),
                         fmt::format("--seed-weighted needs positive values of '{}', but cell {} "
                                     "has {}",
                                     options.channel, c, channel.values[c]));
      cumulative.push_back(sum += channel.values[c]);
    }
  }

  std::mt19937_64 rng(options.seed);
  SeedList seeds;
  for (std::size_t n = 0; n < options.count; ++n) {
    std::size_t pick;
    if (options.weighted) {
      const double u = unitRandom(rng) * cumulative.back();
      pick = std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), u) -
                         cumulative.begin());
      pick = std::min(pick, candidates.size() - 1);
    } else {
      pick =
          std::min(candidates.size() - 1, std::size_t(unitRandom(rng) * double(candidates.size())));
    }
    const std::uint32_t cell = candidates[pick];
    const double width = bricks::AmrField::cellWidth(field.levels()[cell]);
    const glm::dvec3 local(unitRandom(rng), unitRandom(rng), unitRandom(rng));
    const glm::dvec3 p = glm::dvec3(field.lowers()[cell]) + local * width;
    seeds.points.push_back(field.transform().toPhysical(p));
    seeds.origins.push_back(fmt::format("densest-cell seed #{} (cell {})", n, cell));
  }
  return seeds;
}

}  // namespace amrstream::flow
