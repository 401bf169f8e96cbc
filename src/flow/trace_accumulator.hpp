#pragma once
// Collects the rounds of a trace. Rounds arrive as they finish; each holds a few points of many
// lines, so a line's points are spread over the rounds. store() hands them over as they are
// (StoredTraces: read line by line, or assembled into one TraceSet).

#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "round_block.hpp"
#include "stored_traces.hpp"
#include "trace_set.hpp"

namespace amrstream::flow {

// Host bytes a traced line holds at the peak of a trace besides its points: its state, seed
// id, direction, steps, reason, offset and the rounds' bookkeeping. Measured: 2,000,000 and
// 4,000,000 seeds of builtin:rotation at --steps 0 peaked 1.14 GiB apart, 306 bytes a line,
// of which 36 were its point.
inline constexpr std::uint64_t kHeldBytesPerLine = 272;

// Which seed and direction each line traces, in output order.
struct LineLayout {
  std::vector<std::uint32_t> seedIds;
  std::vector<float> directions;  // +1 forward, -1 backward
};

class TraceAccumulator {
 public:
  // `shape` gives the names, the periodic box, withVorticity and precisePositions; its arrays are
  // ignored.
  TraceAccumulator(LineLayout lines, const TraceSet& shape);

  // Takes the round's points; lines whose reason is no longer RUNNING are finished. A round
  // reports each of its lines once (its reports are read on all cores). Rounds hold
  // positionsLow for every point, or for none: the shape's precisePositions requires them, else
  // the first round with points decides for all. Throws std::invalid_argument for a round whose
  // columns do not match its lines, InputError when the lines (kHeldBytesPerLine each) and the
  // points collected pass `maxBytes` (see setMemoryLimit).
  void add(RoundBlock&& round);
  // Takes the reports of a round whose points are kept elsewhere (a device's copy of the round,
  // see takeLines): lines whose reason is no longer RUNNING are finished.
  void addReports(std::span<const shared::LineRound> lines);
  // 0: no limit.
  void setMemoryLimit(std::uint64_t maxBytes) { maxBytes_ = maxBytes; }

  std::size_t lineCount() const { return layout_.seedIds.size(); }
  const LineLayout& layout() const { return layout_; }
  std::size_t finishedLines() const { return finished_; }

  // The TraceSet of all rounds so far; the accumulator is left empty.
  TraceSet assemble();
  // The rounds so far as they are, read line by line (for writers: no assembled copy); the
  // accumulator is left empty.
  StoredTraces store();
  // The lines (seed ids, directions, steps, reasons, offsets) of the rounds taken by addReports,
  // and per round the lines its points belong to; the accumulator is left empty.
  struct Lines {
    TraceSet lines;
    std::vector<std::vector<LinePoints>> runs;
  };
  Lines takeLines();
  // The rounds so far as store() gives them, leaving the accumulator as it is (for traces that
  // go on growing).
  TraceSet snapshot() const;

 private:
  // The lines and runs so far; the accumulator is left empty.
  Lines takeAll();
  // Records the round's reports; returns its runs and its points.
  std::pair<std::vector<LinePoints>, std::uint64_t> takeReports(
      std::span<const shared::LineRound> lines);

  LineLayout layout_;
  TraceSet result_;  // names, periodic box, steps and reasons so far
  std::vector<std::uint64_t> pointsPerLine_;
  std::vector<RoundBlock> rounds_;             // their LineRounds dropped once read
  std::vector<std::vector<LinePoints>> runs_;  // per round, the lines its points belong to
  std::size_t finished_ = 0;
  std::uint64_t points_ = 0;
  std::uint64_t maxBytes_ = 0;
};

}  // namespace amrstream::flow
