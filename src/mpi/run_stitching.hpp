#pragma once
// The lines of a trace over data, put back together from the ranks' runs (data_rounds.hpp), on
// rank 0 or on the rank whose piece holds them: each line's runs in the order it took them, its
// points one polyline, its steps and reason those of its last run, the lines in the order one
// process writes them.

#include <cstdint>
#include <utility>
#include <vector>

#include "flow/trace_accumulator.hpp"
#include "flow/trace_set.hpp"

namespace amrstream::mpi {

// Lines [first, last) of a trace: what one rank writes as its piece.
struct LineRange {
  std::uint32_t first = 0, last = 0;
};

// The lines of `lines` that rank `rank` of `ranks` writes as its piece: contiguous, so that the
// pieces in rank order hold the lines in one process's order.
LineRange pieceLines(std::size_t lines, int rank, int ranks);

// `runs` (data_rounds.hpp) split by the rank whose piece holds their line.
std::vector<flow::TraceSet> runsByPiece(const flow::TraceSet& runs, std::size_t lines, int ranks);

// `parts`: the runs of the lines in `range` (all of them: every rank's runs). `layout`: the seed
// and direction of every line (flow::planLines). Throws std::runtime_error when a line has no
// run or its runs do not end with its end.
flow::TraceSet stitchRuns(std::vector<flow::TraceSet> parts, const flow::LineLayout& layout,
                          LineRange range);
inline flow::TraceSet stitchRuns(std::vector<flow::TraceSet> parts,
                                 const flow::LineLayout& layout) {
  return stitchRuns(std::move(parts), layout,
                    {0, static_cast<std::uint32_t>(layout.seedIds.size())});
}

}  // namespace amrstream::mpi
