#pragma once
// The traces of every rank read as those of one process: each rank's part holds the lines of its
// seeds (seed ids already global), and the lines are read in the order one process writes them,
// forward lines before backward ones, each direction by seed id. No point is copied.

#include <cstdint>
#include <span>
#include <vector>

#include "flow/trace_view.hpp"

namespace amrstream::mpi {

class GatheredTraces final : public flow::TraceView {
 public:
  // The parts' names and flags must agree (they come from one volume and one set of options);
  // the first part's are used. Throws std::invalid_argument when two lines share a seed and a
  // direction.
  explicit GatheredTraces(std::vector<flow::TraceSet> parts);

  const flow::TraceSet& lines() const override { return lines_; }
  std::span<const float> column(flow::PointColumn column, std::size_t line,
                                std::vector<float>& scratch) const override;

 private:
  struct Source {
    std::uint32_t part;
    std::uint64_t line;
  };

  std::vector<flow::TraceSet> parts_;
  std::vector<flow::TraceSetView> views_;
  flow::TraceSet lines_;         // per-line data and offsets over all parts; no point columns
  std::vector<Source> sources_;  // per line of lines_
};

}  // namespace amrstream::mpi
