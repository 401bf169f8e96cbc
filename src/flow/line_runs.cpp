#include "line_runs.hpp"

#include <tbb/parallel_for.h>

#include <stdexcept>

namespace amrstream::flow {

LineRuns::LineRuns(std::size_t lineCount, std::vector<std::vector<LinePoints>>& runs) {
  for (const std::vector<LinePoints>& round : runs)
    for (const LinePoints& r : round)
      if (r.line >= lineCount) throw std::invalid_argument("LineRuns: no such line");
  // A round names each line once, so its entries are counted and placed by one task each.
  std::vector<std::uint64_t> counts(lineCount + 1, 0);
  for (const std::vector<LinePoints>& round : runs)
    tbb::parallel_for(std::size_t(0), round.size(),
                      [&](std::size_t i) { ++counts[round[i].line + 1]; });
  for (std::size_t i = 0; i < lineCount; ++i) counts[i + 1] += counts[i];
  offsets_ = counts;
  runs_.resize(counts.back());
  std::vector<std::uint32_t> firsts;
  for (std::uint32_t round = 0; round < runs.size(); ++round) {
    const std::vector<LinePoints>& placed = runs[round];
    firsts.resize(placed.size());
    std::uint32_t first = 0;
    for (std::size_t i = 0; i < placed.size(); ++i) {
      firsts[i] = first;
      first += placed[i].points;
    }
    tbb::parallel_for(std::size_t(0), placed.size(), [&](std::size_t i) {
      const LinePoints& r = placed[i];
      runs_[counts[r.line]++] = {round, r.points, firsts[i]};
    });
    std::vector<LinePoints>().swap(runs[round]);
  }
}

std::uint64_t LineRuns::pointCount(std::size_t line) const {
  std::uint64_t points = 0;
  for (const PointRun& run : of(line)) points += run.count;
  return points;
}

}  // namespace amrstream::flow
