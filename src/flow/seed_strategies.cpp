#include "seed_strategies.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <optional>
#include <random>
#include <span>

#include "amrstream/error.hpp"
#include "sampler.hpp"

namespace amrstream::flow {

namespace {

// 53 random bits -> [0, 1), the same on every standard library (see randomSeedsInBox).
double unitRandom(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

// A float's bits as an unsigned key in the floats' order (-0 just below +0).
std::uint32_t orderKey(float value) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
  return bits & 0x80000000u ? ~bits : bits | 0x80000000u;
}

}  // namespace

// Two histograms of 2^16 buckets: of the keys' high halves, then of the low halves of the keys
// in the bucket holding the rank.
float valueAtRank(std::span<const float> values, std::size_t rank, const SharedCells* shared) {
  using Histogram = std::vector<std::uint64_t>;
  const auto histogram = [&](auto bucketOf) {
    tbb::enumerable_thread_specific<Histogram> perThread(Histogram(std::size_t(1) << 16, 0));
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, values.size(), std::size_t(1) << 16),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        Histogram& h = perThread.local();
                        for (std::size_t i = range.begin(); i != range.end(); ++i) {
                          if (shared && !shared->owned[i]) continue;
                          if (const auto b = bucketOf(orderKey(values[i]))) ++h[*b];
                        }
                      });
    Histogram all(std::size_t(1) << 16, 0);
    for (const Histogram& h : perThread)
      for (std::size_t k = 0; k < all.size(); ++k) all[k] += h[k];
    if (shared) shared->sumCounts(all);
    return all;
  };
  // The bucket holding the rank, and the rank within it.
  const auto locate = [](const Histogram& h, std::size_t& within) {
    std::uint32_t bucket = 0;
    while (within >= h[bucket]) within -= h[bucket++];
    return bucket;
  };
  std::size_t within = rank;
  const std::uint32_t high = locate(
      histogram([](std::uint32_t key) { return std::optional<std::uint32_t>(key >> 16); }), within);
  const std::uint32_t low = locate(
      histogram([high](std::uint32_t key) {
        return key >> 16 == high ? std::optional<std::uint32_t>(key & 0xffffu) : std::nullopt;
      }),
      within);
  const std::uint32_t key = high << 16 | low;
  const std::uint32_t bits = key & 0x80000000u ? key & 0x7fffffffu : ~key;
  return std::bit_cast<float>(bits);
}

namespace {

// The indices of the values at or above `threshold`, in increasing order, found in parallel;
// with `owned`, among those where it is not 0.
std::vector<std::uint32_t> indicesAtOrAbove(std::span<const float> values, float threshold,
                                            std::span<const std::uint8_t> owned) {
  constexpr std::size_t kBlock = std::size_t(1) << 16;
  const std::size_t blocks = (values.size() + kBlock - 1) / kBlock;
  const auto counted = [&](std::size_t i) {
    return values[i] >= threshold && (owned.empty() || owned[i]);
  };
  std::vector<std::size_t> counts(blocks + 1, 0);
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    for (std::size_t i = b * kBlock; i < std::min(values.size(), (b + 1) * kBlock); ++i)
      counts[b + 1] += counted(i);
  });
  std::partial_sum(counts.begin(), counts.end(), counts.begin());
  std::vector<std::uint32_t> out(counts.back());
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    std::size_t at = counts[b];
    for (std::size_t i = b * kBlock; i < std::min(values.size(), (b + 1) * kBlock); ++i)
      if (counted(i)) out[at++] = std::uint32_t(i);
  });
  return out;
}

// The candidates' cells and values: this process's, or with `shared` every process's.
std::pair<std::vector<std::uint32_t>, std::vector<float>> candidateCells(
    std::span<const float> values, float threshold, const SharedCells* shared) {
  std::vector<std::uint32_t> cells =
      indicesAtOrAbove(values, threshold, shared ? shared->owned : std::span<const std::uint8_t>());
  if (shared) {
    std::vector<std::pair<std::uint32_t, float>> mine;
    mine.reserve(cells.size());
    for (const std::uint32_t c : cells) mine.emplace_back(c, values[c]);
    const std::vector<std::pair<std::uint32_t, float>> all = shared->gatherCells(std::move(mine));
    std::pair<std::vector<std::uint32_t>, std::vector<float>> result;
    for (const auto& [cell, value] : all) {
      result.first.push_back(cell);
      result.second.push_back(value);
    }
    return result;
  }
  std::vector<float> candidateValues(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) candidateValues[i] = values[cells[i]];
  return {std::move(cells), std::move(candidateValues)};
}

}  // namespace

SeedList seedsAlongLine(glm::dvec3 from, glm::dvec3 to, std::size_t count) {
  SeedList seeds;
  for (std::size_t i = 0; i < count; ++i) {
    const double t = count == 1 ? 0.5 : double(i) / double(count - 1);
    seeds.points.push_back(from + t * (to - from));
  }
  seeds.origin = [](std::size_t i) { return fmt::format("{{seed_line}} point #{}", i); };
  return seeds;
}

SeedList seedsOnGrid(glm::dvec3 lower, glm::dvec3 upper, glm::ivec3 counts) {
  SeedList seeds;
  for (int k = 0; k < counts.z; ++k)
    for (int j = 0; j < counts.y; ++j)
      for (int i = 0; i < counts.x; ++i) {
        const glm::dvec3 t = (glm::dvec3(i, j, k) + 0.5) / glm::dvec3(counts);
        seeds.points.push_back(lower + t * (upper - lower));
      }
  seeds.origin = [counts](std::size_t n) {
    const std::size_t x = std::size_t(counts.x), y = std::size_t(counts.y);
    return fmt::format("{{seed_grid}} point ({}, {}, {})", n % x, n / x % y, n / (x * y));
  };
  return seeds;
}

bool insideACell(const VectorVolume& volume, glm::dvec3 cellUnits) {
  if (volume.surelyInACell(cellUnits)) return true;
  const std::int32_t region = locateRegion(volume, toCellPoint(cellUnits));
  if (region < 0) return false;
  const shared::Region& r = volume.regions.regions[std::size_t(region)];
  for (std::uint32_t i = 0; i < r.brickCount; ++i) {
    const shared::Brick& b = volume.bricks[volume.regions.regionBricks[r.brickOffset + i]];
    const glm::dvec3 lower(b.lower), upper = lower + glm::dvec3(b.size) * double(1 << b.level);
    if (glm::all(glm::greaterThanEqual(cellUnits, lower)) &&
        glm::all(glm::lessThan(cellUnits, upper)))
      return true;
  }
  return false;
}

SeedList randomSeedsInCells(const VectorVolume& volume, glm::dvec3 lower, glm::dvec3 upper,
                            std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  SeedList seeds;
  seeds.points.reserve(count);
  const std::size_t maxDraws = 1000 * std::max<std::size_t>(count, 1);
  std::size_t draws = 0;
  // Points are drawn in order and tested in parallel, a batch at a time; the seeds are the first
  // `count` drawn inside a cell, as if tested one by one.
  std::vector<glm::dvec3> batch;
  std::vector<char> inside;
  while (seeds.points.size() < count) {
    if (draws == maxDraws)
      throw InputError("random seeds",
                       fmt::format("only {} of {} random points in the box ({:g}, {:g}, {:g}) .. "
                                   "({:g}, {:g}, {:g}) fell inside cells: the box is nearly all "
                                   "holes; give a {{seed_box}} around the data or {{seed_density}}",
                                   seeds.points.size(), draws, lower.x, lower.y, lower.z, upper.x,
                                   upper.y, upper.z));
    const std::size_t missing = count - seeds.points.size();
    batch.resize(std::min(maxDraws - draws, std::max<std::size_t>(missing + missing / 4, 1024)));
    for (glm::dvec3& p : batch) {
      const glm::dvec3 t(unitRandom(rng), unitRandom(rng), unitRandom(rng));
      p = lower + t * (upper - lower);
    }
    inside.resize(batch.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch.size(), 1024), [&](const auto& r) {
      for (std::size_t i = r.begin(); i < r.end(); ++i)
        inside[i] = insideACell(volume, volume.transform.toCellUnits(batch[i]));
    });
    for (std::size_t i = 0; i < batch.size() && seeds.points.size() < count; ++i) {
      ++draws;
      if (inside[i]) seeds.points.push_back(batch[i]);
    }
  }
  seeds.origin = [](std::size_t i) { return fmt::format("random seed #{}", i); };
  return seeds;
}

SeedList seedsInDensestCells(const bricks::AmrField& field, const DensestCellsOptions& options) {
  const Channel& channel = field.channel(options.channel);  // throws if absent
  if (!(options.percentile >= 0.0 && options.percentile <= 100.0))
    throw settingError("seed_percentile",
                       fmt::format("{} is not a percentile in [0, 100]", options.percentile));

  // The value at the percentile (nearest rank), then every cell at or above it.
  const std::size_t rank =
      std::min(channel.values.size() - 1,
               std::size_t(std::floor(options.percentile / 100.0 * double(channel.values.size()))));
  const float threshold = valueAtRank(channel.values, rank, options.shared);
  const auto [candidates, candidateValues] =
      candidateCells(channel.values, threshold, options.shared);

  std::vector<double> cumulative;
  if (options.weighted) {
    cumulative.reserve(candidates.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (!(candidateValues[i] > 0.0f))
        throw InputError(field.source(),
                         fmt::format("{{seed_weighted}} needs positive values of '{}', but cell {} "
                                     "has {}",
                                     options.channel, candidates[i], candidateValues[i]));
      cumulative.push_back(sum += candidateValues[i]);
    }
  }

  std::mt19937_64 rng(options.seed);
  SeedList seeds;
  std::vector<std::uint32_t> seedCells;
  seeds.points.reserve(options.count);
  seedCells.reserve(options.count);
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
    seedCells.push_back(cell);
  }
  seeds.origin = [cells = std::move(seedCells)](std::size_t n) {
    return fmt::format("densest-cell seed #{} (cell {})", n, cells[n]);
  };
  return seeds;
}

}  // namespace amrstream::flow
