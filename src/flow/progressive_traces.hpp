#pragma once
// Traces that grow a few steps at a time, for the viewer's progressive tracing: each advance()
// runs one round of any RoundTracer (the CPU reference or a GPU backend, one thread per live
// line). The lines equal one run of maxSteps: a line continued in the next round is the line
// traced in one go. What the last round added is at hand on its own (recent()), so that a viewer
// can append to its tubes; the whole traces are assembled only when asked for.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "growing_traces.hpp"
#include "round_tracer.hpp"
#include "trace_accumulator.hpp"
#include "trace_set.hpp"

namespace amrstream::flow {

class ProgressiveTraces final : public GrowingTraces {
 public:
  // `shape` gives the names and the periodic box of the traces (see TraceAccumulator).
  ProgressiveTraces(std::unique_ptr<RoundTracer> tracer, LineLayout lines, const TraceSet& shape);

  // Advances the live lines by up to `steps` steps each; returns the particle-steps taken.
  std::size_t advance(std::uint32_t steps) override;

  bool finished() const override { return tracer_->liveLines() == 0; }
  std::size_t runningCount() const override { return tracer_->liveLines(); }
  std::size_t lineCount() const override { return accumulator_.lineCount(); }
  std::size_t stepsTaken() const override { return stepsTaken_; }
  // The lines so far; reasons are AMRSTREAM_REASON_RUNNING until a line ends. Assembled on the
  // first call after an advance().
  const TraceSet& traces() const override;
  // The lines the last advance() moved, in its order, each with the points the round added and,
  // before them, its last point from the rounds before (when it had one and the round added
  // any): the polylines that extend the traces. Seed ids, directions, steps and reasons are the
  // lines'.
  const TraceSet& recent() const override { return recent_; }

 private:
  std::unique_ptr<RoundTracer> tracer_;
  TraceAccumulator accumulator_;
  mutable TraceSet traces_;
  mutable bool stale_ = true;
  TraceSet recent_;
  TraceSet tails_;  // one point slot per line: point i belongs to line i, where hasTail_[i]
  std::vector<bool> hasTail_;
  std::vector<std::uint32_t> lineSteps_;
  std::size_t stepsTaken_ = 0;
};

}  // namespace amrstream::flow
