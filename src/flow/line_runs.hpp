#pragma once
// Where each line's points lie among the rounds that traced them: each round holds a few points
// of many lines, line after line in the round's thread order, so a line's points are runs in
// successive rounds.

#include <cstdint>
#include <span>
#include <vector>

#include "round_block.hpp"

namespace amrstream::flow {

struct PointRun {
  std::uint32_t round;
  std::uint32_t count;  // points
  std::uint32_t first;  // the run's first point in its round (a round holds < 2^32 points)
};

class LineRuns {
 public:
  LineRuns() : offsets_(1, 0) {}
  // runs[r] names, in order, the lines that round r's points belong to; each list is released
  // once placed, so that the lists and the table are held once. Throws std::invalid_argument for
  // a line >= lineCount.
  LineRuns(std::size_t lineCount, std::vector<std::vector<LinePoints>>& runs);

  // The runs of `line`, in round order.
  std::span<const PointRun> of(std::size_t line) const {
    return std::span(runs_).subspan(offsets_[line], offsets_[line + 1] - offsets_[line]);
  }
  std::uint64_t pointCount(std::size_t line) const;

 private:
  std::vector<std::uint64_t> offsets_;  // the runs of line i: runs_[offsets_[i] ..]
  std::vector<PointRun> runs_;
};

}  // namespace amrstream::flow
