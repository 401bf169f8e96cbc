#include "progressive_traces.hpp"

#include <algorithm>

namespace amrstream::flow {

namespace {

// Copies point `from` of `source` (a TraceSet or a RoundBlock of `channels` values per point) to
// the end of `target`'s columns.
template <typename Points>
void appendPoint(TraceSet& target, const Points& source, std::size_t channels, std::uint64_t from) {
  target.positions.push_back(source.positions[from]);
  if (!source.positionsLow.empty()) target.positionsLow.push_back(source.positionsLow[from]);
  target.times.push_back(source.times[from]);
  target.vectors.push_back(source.vectors[from]);
  for (std::size_t c = 0; c < channels; ++c)
    target.channels.push_back(source.channels[from * channels + c]);
  if (!source.vorticity.empty()) target.vorticity.push_back(source.vorticity[from]);
}

// Writes point `from` of the round over point `to` of `target`.
void setPoint(TraceSet& target, std::uint64_t to, const RoundBlock& source, std::size_t channels,
              std::uint64_t from) {
  target.positions[to] = source.positions[from];
  if (!source.positionsLow.empty()) target.positionsLow[to] = source.positionsLow[from];
  target.times[to] = source.times[from];
  target.vectors[to] = source.vectors[from];
  std::copy_n(source.channels.begin() + std::ptrdiff_t(from * channels), channels,
              target.channels.begin() + std::ptrdiff_t(to * channels));
  if (!source.vorticity.empty()) target.vorticity[to] = source.vorticity[from];
}

TraceSet emptyLike(const TraceSet& shape, bool precise) {
  TraceSet set;
  set.vectorName = shape.vectorName;
  set.channelNames = shape.channelNames;
  set.periodic = shape.periodic;
  set.withVorticity = shape.withVorticity;
  set.precisePositions = precise;
  return set;
}

}  // namespace

ProgressiveTraces::ProgressiveTraces(std::unique_ptr<RoundTracer> tracer, LineLayout lines,
                                     const TraceSet& shape)
    : tracer_(std::move(tracer)), accumulator_(std::move(lines), shape) {
  lineSteps_.assign(accumulator_.lineCount(), 0);
  hasTail_.assign(accumulator_.lineCount(), false);
  recent_ = emptyLike(shape, shape.precisePositions);
}

const TraceSet& ProgressiveTraces::traces() const {
  if (stale_) {
    traces_ = accumulator_.snapshot();
    stale_ = false;
  }
  return traces_;
}

std::size_t ProgressiveTraces::advance(std::uint32_t steps) {
  if (finished() || steps == 0) return 0;
  RoundBlock round = tracer_->advance(steps);
  std::size_t taken = 0;
  for (const shared::LineRound& line : round.lines) {
    taken += line.steps - lineSteps_[line.line];
    lineSteps_[line.line] = line.steps;
  }

  const bool precise = !round.positionsLow.empty();
  const std::size_t channels = recent_.channelCount();
  if (tails_.times.empty()) {  // one slot per line, once the first round says what points hold
    const std::size_t lines = hasTail_.size();
    tails_ = emptyLike(recent_, precise);
    tails_.positions.resize(lines);
    if (precise) tails_.positionsLow.resize(lines);
    tails_.times.resize(lines);
    tails_.vectors.resize(lines);
    tails_.channels.resize(lines * channels);
    if (tails_.withVorticity) tails_.vorticity.resize(lines);
  }
  const LineLayout& layout = accumulator_.layout();
  TraceSet recent = emptyLike(recent_, precise);
  std::uint64_t point = 0;
  for (const shared::LineRound& line : round.lines) {
    recent.seedIds.push_back(layout.seedIds[line.line]);
    recent.directions.push_back(layout.directions[line.line]);
    recent.steps.push_back(line.steps);
    recent.reasons.push_back(line.reason);
    if (hasTail_[line.line] && line.points > 0) appendPoint(recent, tails_, channels, line.line);
    for (std::uint32_t k = 0; k < line.points; ++k) appendPoint(recent, round, channels, point + k);
    recent.offsets.push_back(recent.positions.size());
    if (line.points > 0) {
      setPoint(tails_, line.line, round, channels, point + line.points - 1);
      hasTail_[line.line] = true;
    }
    point += line.points;
  }
  recent_ = std::move(recent);
  accumulator_.add(std::move(round));
  stale_ = true;
  stepsTaken_ += taken;
  return taken;
}

}  // namespace amrstream::flow
