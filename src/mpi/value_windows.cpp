#include "value_windows.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <span>

namespace amrstream::mpi {

formats::ValueWindow partWindow(const DataPartition& partition, int rank, double grow,
                                const CellBox& domain, const flow::PeriodicAxes& periodic) {
  const glm::dvec3 lower = glm::dvec3(partition.lower[std::size_t(rank)]) - grow;
  const glm::dvec3 upper = glm::dvec3(partition.upper[std::size_t(rank)]) + grow;
  const glm::dvec3 period(domain.upper - domain.lower);
  constexpr double kLimit = 0x1p31 - 1.0;
  const auto cells = [&](glm::dvec3 v) {
    return glm::ivec3(glm::clamp(v, glm::dvec3(-kLimit), glm::dvec3(kLimit)));
  };
  formats::ValueWindow window;
  for (const glm::ivec3& s : flow::periodicShifts(periodic))
    window.boxes.push_back({cells(glm::floor(lower + glm::dvec3(s) * period)),
                            cells(glm::ceil(upper + glm::dvec3(s) * period))});
  return window;
}

std::vector<std::uint8_t> ownedCells(const bricks::AmrField& field, const DataPartition& partition,
                                     int rank) {
  std::vector<std::uint8_t> owned(field.cellCount());
  const std::span<const glm::ivec3> lowers = field.lowers();
  const std::span<const std::uint8_t> levels = field.levels();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, owned.size(), std::size_t(1) << 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t c = range.begin(); c != range.end(); ++c) {
                        const glm::dvec3 centre =
                            glm::dvec3(lowers[c]) +
                            0.5 * double(bricks::AmrField::cellWidth(levels[c]));
                        owned[c] = partition.ownerOf(centre) == rank;
                      }
                    });
  return owned;
}

flow::SharedCells shareOverRanks(const MpiWorld& world) {
  flow::SharedCells shared;
  shared.sumCounts = [&world](std::vector<std::uint64_t>& counts) { world.sumOverRanks(counts); };
  shared.gatherCells = [&world](std::vector<std::pair<std::uint32_t, float>> mine) {
    // Each rank's cells as (index, value bits) words, gathered in rank order, then merged.
    std::vector<std::uint64_t> words(mine.size());
    for (std::size_t i = 0; i < mine.size(); ++i)
      words[i] = std::uint64_t(mine[i].first) << 32 | std::bit_cast<std::uint32_t>(mine[i].second);
    const std::vector<std::byte> bytes = world.gatherToAll(std::as_bytes(std::span(words)));
    std::vector<std::uint64_t> all(bytes.size() / sizeof(std::uint64_t));
    std::memcpy(all.data(), bytes.data(), all.size() * sizeof(std::uint64_t));
    std::sort(all.begin(), all.end());
    std::vector<std::pair<std::uint32_t, float>> cells(all.size());
    for (std::size_t i = 0; i < all.size(); ++i)
      cells[i] = {std::uint32_t(all[i] >> 32), std::bit_cast<float>(std::uint32_t(all[i]))};
    return cells;
  };
  return shared;
}

}  // namespace amrstream::mpi
