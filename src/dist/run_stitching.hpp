#pragma once
// The lines of a trace over data, put back together on rank 0 from the ranks' runs
// (data_rounds.hpp): each line's runs in the order it took them, its points one polyline, its
// steps and reason those of its last run, the lines in the order one process writes them.

#include <vector>

#include "flow/trace_accumulator.hpp"
#include "flow/trace_set.hpp"

namespace amrstream::dist {

// `parts`: every rank's runs. `layout`: the seed and direction of every line (flow::planLines).
// Throws std::runtime_error when a line has no run or its runs do not end with its end.
flow::TraceSet stitchRuns(std::vector<flow::TraceSet> parts, const flow::LineLayout& layout);

}  // namespace amrstream::dist
