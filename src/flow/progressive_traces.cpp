#include "progressive_traces.hpp"

namespace amrstream::flow {

ProgressiveTraces::ProgressiveTraces(std::unique_ptr<RoundTracer> tracer, LineLayout lines,
                                     const TraceSet& shape)
    : tracer_(std::move(tracer)), accumulator_(std::move(lines), shape) {
  lineSteps_.assign(accumulator_.lineCount(), 0);
  traces_ = accumulator_.snapshot();
}

std::size_t ProgressiveTraces::advance(std::uint32_t steps) {
  if (finished() || steps == 0) return 0;
  RoundBlock round = tracer_->advance(steps);
  std::size_t taken = 0;
  for (const shared::LineRound& line : round.lines) {
    taken += line.steps - lineSteps_[line.line];
    lineSteps_[line.line] = line.steps;
  }
  accumulator_.add(std::move(round));
  traces_ = accumulator_.snapshot();
  stepsTaken_ += taken;
  return taken;
}

}  // namespace amrstream::flow
