#pragma once
// Traces as the rounds of a tracer left them: each round's points in one block, line after line
// in the round's thread order, so a line's points are spread over the rounds. Reading a line's
// column gathers its runs (or, for a line that one round holds whole, points into that round).

#include <cstdint>
#include <vector>

#include "line_runs.hpp"
#include "round_block.hpp"
#include "trace_view.hpp"

namespace amrstream::flow {

class StoredTraces final : public TraceView {
 public:
  // `lines` holds every line's seed id, direction, steps, reason and offsets, and says which
  // columns the rounds hold (withVorticity, precisePositions; its point columns are ignored);
  // runs[r] names, in order, the lines that round r's points belong to (the rounds' own
  // LineRounds are not read, and may have been dropped).
  StoredTraces(TraceSet lines, std::vector<RoundBlock> rounds,
               std::vector<std::vector<LinePoints>> runs);

  const TraceSet& lines() const override { return lines_; }
  // The points gathered line after line, one column at a time, each round's copy of a column
  // released once it is gathered: the peak is the result plus one column, not twice the result.
  TraceSet assemble() &&;
  std::span<const float> column(PointColumn column, std::size_t line,
                                std::vector<float>& scratch) const override;

 private:
  TraceSet lines_;
  std::vector<RoundBlock> rounds_;
  LineRuns runs_;
};

}  // namespace amrstream::flow
