#include "line_runs.hpp"

#include <stdexcept>

namespace amrstream::flow {

LineRuns::LineRuns(std::size_t lineCount, std::vector<std::vector<LinePoints>>& runs) {
  std::vector<std::uint64_t> counts(lineCount + 1, 0);
  for (const std::vector<LinePoints>& round : runs)
    for (const LinePoints& r : round) {
      if (r.line >= lineCount) throw std::invalid_argument("LineRuns: no such line");
      ++counts[r.line + 1];
    }
  for (std::size_t i = 0; i < lineCount; ++i) counts[i + 1] += counts[i];
  offsets_ = counts;
  runs_.resize(counts.back());
  for (std::uint32_t round = 0; round < runs.size(); ++round) {
    std::uint32_t first = 0;
    for (const LinePoints& r : runs[round]) {
      runs_[counts[r.line]++] = {round, r.points, first};
      first += r.points;
    }
    std::vector<LinePoints>().swap(runs[round]);
  }
}

std::uint64_t LineRuns::pointCount(std::size_t line) const {
  std::uint64_t points = 0;
  for (const PointRun& run : of(line)) points += run.count;
  return points;
}

}  // namespace amrstream::flow
