#pragma once
// Traces that grow a few steps at a time, for the viewer's progressive tracing: each advance()
// runs one round of any RoundTracer (the CPU reference or a GPU backend, one thread per live
// line) and the traces so far are kept as a TraceSet. The lines equal one run of maxSteps: a
// line continued in the next round is the line traced in one go.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "round_tracer.hpp"
#include "trace_accumulator.hpp"
#include "trace_set.hpp"

namespace amrstream::flow {

class ProgressiveTraces {
 public:
  // `shape` gives the names and the periodic box of the traces (see TraceAccumulator).
  ProgressiveTraces(std::unique_ptr<RoundTracer> tracer, LineLayout lines, const TraceSet& shape);

  // Advances the live lines by up to `steps` steps each; returns the particle-steps taken.
  std::size_t advance(std::uint32_t steps);

  bool finished() const { return tracer_->liveLines() == 0; }
  std::size_t runningCount() const { return tracer_->liveLines(); }
  std::size_t stepsTaken() const { return stepsTaken_; }
  // The lines so far; reasons are AMRSTREAM_REASON_RUNNING until a line ends.
  const TraceSet& traces() const { return traces_; }

 private:
  std::unique_ptr<RoundTracer> tracer_;
  TraceAccumulator accumulator_;
  TraceSet traces_;
  std::vector<std::uint32_t> lineSteps_;
  std::size_t stepsTaken_ = 0;
};

}  // namespace amrstream::flow
