#pragma once
// Collects the rounds of a trace into one TraceSet. Rounds arrive as they finish; each holds a
// few points of many lines, so a line's points are spread over the rounds. assemble() gathers
// them line by line, one array at a time, releasing each round's copy of that array as it goes:
// the peak is the result plus its largest array, not twice the result.

#include <cstdint>
#include <string>
#include <vector>

#include "round_block.hpp"
#include "trace_set.hpp"

namespace amrstream::flow {

// Which seed and direction each line traces, in output order.
struct LineLayout {
  std::vector<std::uint32_t> seedIds;
  std::vector<float> directions;  // +1 forward, -1 backward
};

class TraceAccumulator {
 public:
  // `shape` gives the names and the periodic box; its arrays are ignored.
  TraceAccumulator(LineLayout lines, const TraceSet& shape);

  // Takes the round's points; lines whose reason is no longer RUNNING are finished. Throws
  // InputError when the points collected pass `maxBytes` (see setMemoryLimit).
  void add(RoundBlock&& round);
  // 0: no limit.
  void setMemoryLimit(std::uint64_t maxBytes) { maxBytes_ = maxBytes; }

  std::size_t lineCount() const { return layout_.seedIds.size(); }
  std::size_t finishedLines() const { return finished_; }
  std::uint64_t pointCount() const { return points_; }

  // The TraceSet of all rounds so far; the accumulator is left empty.
  TraceSet assemble();
  // The same, leaving the accumulator as it is (for traces that go on growing).
  TraceSet snapshot() const;

 private:
  struct StoredRound {
    RoundBlock block;
    std::vector<std::uint64_t> destinations;  // per line of the round: points of it before
  };

  // Rounds is std::vector<StoredRound>, const for a snapshot; `release` frees what is copied.
  template <typename Rounds>
  static TraceSet gatherAll(const TraceAccumulator& from, Rounds& rounds, bool release);

  LineLayout layout_;
  TraceSet result_;  // names, periodic box, steps and reasons so far
  std::vector<std::uint64_t> pointsPerLine_;
  std::vector<StoredRound> rounds_;
  std::size_t finished_ = 0;
  std::uint64_t points_ = 0;
  std::uint64_t maxBytes_ = 0;
};

}  // namespace amrstream::flow
