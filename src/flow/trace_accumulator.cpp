#include "trace_accumulator.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "amrstream/error.hpp"

namespace amrstream::flow {

TraceAccumulator::TraceAccumulator(LineLayout lines, const TraceSet& shape)
    : layout_(std::move(lines)), pointsPerLine_(layout_.seedIds.size(), 0) {
  if (layout_.directions.size() != layout_.seedIds.size())
    throw std::invalid_argument("TraceAccumulator: one direction per line");
  result_.vectorName = shape.vectorName;
  result_.channelNames = shape.channelNames;
  result_.periodic = shape.periodic;
  result_.withVorticity = shape.withVorticity;
  result_.precisePositions = shape.precisePositions;
  result_.steps.assign(lineCount(), 0);
  result_.reasons.assign(lineCount(), AMRSTREAM_REASON_RUNNING);
}

void TraceAccumulator::add(RoundBlock&& round) {
  const std::size_t channels = result_.channelCount();
  std::uint64_t points = 0;
  for (const shared::LineRound& r : round.lines) points += r.points;
  // Unless the shape says so, the first round with points tells whether positions are precise.
  const bool precise = result_.precisePositions || (points_ == 0 && !round.positionsLow.empty());
  if (round.positions.size() != points || round.times.size() != points ||
      round.vectors.size() != points || round.channels.size() != points * channels ||
      round.vorticity.size() != (result_.withVorticity ? points : 0) ||
      round.positionsLow.size() != (precise ? points : 0))
    throw std::invalid_argument("TraceAccumulator: a round's arrays do not match its lines");

  const std::uint64_t bytes =
      lineCount() * kHeldBytesPerLine +
      (points_ + points) * TraceSet::bytesPerPoint(channels, result_.withVorticity, precise);
  if (maxBytes_ > 0 && bytes > maxBytes_)
    throw InputError("traces", fmt::format("the traces grew past {:.1f} GiB, the limit for this "
                                           "machine, with {} of {} lines finished; trace fewer "
                                           "seeds or steps, or use {{endpoints_only}}",
                                           double(maxBytes_) / 0x1p30, finished_, lineCount()));

  std::vector<LinePoints> runs = takeReports(round.lines).first;
  points_ += points;
  result_.precisePositions = precise;
  std::vector<shared::LineRound>().swap(round.lines);  // 16 bytes a line a round: keep 8
  rounds_.push_back(std::move(round));
  runs_.push_back(std::move(runs));
}

std::pair<std::vector<LinePoints>, std::uint64_t> TraceAccumulator::takeReports(
    std::span<const shared::LineRound> lines) {
  for (const shared::LineRound& r : lines)
    if (r.line >= lineCount()) throw std::invalid_argument("TraceAccumulator: no such line");
  std::vector<LinePoints> runs(lines.size());
  struct Counts {
    std::uint64_t points = 0;
    std::size_t finished = 0;
  };
  // Each line appears once in a round, so the lines' entries are written by one task each.
  const Counts counts = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, lines.size(), std::size_t(1) << 14), Counts{},
      [&](const tbb::blocked_range<std::size_t>& range, Counts c) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          const shared::LineRound& r = lines[i];
          runs[i] = {r.line, r.points};
          c.points += r.points;
          pointsPerLine_[r.line] += r.points;
          result_.steps[r.line] = r.steps;
          if (r.reason != AMRSTREAM_REASON_RUNNING) {
            result_.reasons[r.line] = r.reason;
            ++c.finished;
          }
        }
        return c;
      },
      [](const Counts& a, const Counts& b) {
        return Counts{a.points + b.points, a.finished + b.finished};
      });
  finished_ += counts.finished;
  return {std::move(runs), counts.points};
}

void TraceAccumulator::addReports(std::span<const shared::LineRound> lines) {
  if (!rounds_.empty())
    throw std::logic_error("TraceAccumulator: rounds with points and rounds without mixed");
  auto [runs, points] = takeReports(lines);
  points_ += points;
  runs_.push_back(std::move(runs));
}

TraceSet TraceAccumulator::snapshot() const {
  TraceAccumulator copy = *this;
  return copy.store().assemble();
}

TraceAccumulator::Lines TraceAccumulator::takeAll() {
  TraceSet lines = std::move(result_);
  lines.seedIds = std::move(layout_.seedIds);
  lines.directions = std::move(layout_.directions);
  lines.offsets.assign(pointsPerLine_.size() + 1, 0);
  for (std::size_t line = 0; line < pointsPerLine_.size(); ++line)
    lines.offsets[line + 1] = lines.offsets[line] + pointsPerLine_[line];
  std::vector<std::vector<LinePoints>> runs = std::move(runs_);
  const std::uint64_t limit = maxBytes_;
  *this = TraceAccumulator(LineLayout{}, lines);
  maxBytes_ = limit;
  return {std::move(lines), std::move(runs)};
}

StoredTraces TraceAccumulator::store() {
  std::vector<RoundBlock> blocks = std::move(rounds_);
  Lines all = takeAll();
  return {std::move(all.lines), std::move(blocks), std::move(all.runs)};
}

TraceAccumulator::Lines TraceAccumulator::takeLines() {
  if (!rounds_.empty())
    throw std::logic_error("TraceAccumulator: takeLines() for rounds that brought their points");
  return takeAll();
}

TraceSet TraceAccumulator::assemble() { return store().assemble(); }

}  // namespace amrstream::flow
