#include "trace_accumulator.hpp"

#include <fmt/format.h>

#include <tbb/parallel_for.h>

#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "util/input_error.hpp"

namespace amrstream::flow {

namespace {

// Copies one array of every stored round into `target` at the rounds' destinations (in units of
// `width` elements per point); with `release`, frees each round's array once it is copied.
template <typename T, typename Rounds>
void gather(Column<T>& target, std::uint64_t points, std::size_t width, Rounds& rounds,
            Column<T> RoundBlock::*array, const std::vector<std::uint64_t>& offsets,
            bool release) {
  target.resize(points * width);
  if (width == 0) return;
  for (auto& round : rounds) {
    auto& source = round.block.*array;
    const std::vector<shared::LineRound>& lines = round.block.lines;
    std::vector<std::uint64_t> starts(lines.size() + 1, 0);
    for (std::size_t i = 0; i < lines.size(); ++i) starts[i + 1] = starts[i] + lines[i].points;
    tbb::parallel_for(std::size_t(0), lines.size(), [&](std::size_t i) {
      if (lines[i].points == 0) return;
      std::memcpy(target.data() + (offsets[lines[i].line] + round.destinations[i]) * width,
                  source.data() + starts[i] * width,
                  std::size_t(lines[i].points) * width * sizeof(T));
    });
    if constexpr (!std::is_const_v<std::remove_reference_t<decltype(source)>>)
      if (release) Column<T>().swap(source);
  }
}

}  // namespace

TraceAccumulator::TraceAccumulator(LineLayout lines, const TraceSet& shape)
    : layout_(std::move(lines)), pointsPerLine_(layout_.seedIds.size(), 0) {
  if (layout_.directions.size() != layout_.seedIds.size())
    throw std::invalid_argument("TraceAccumulator: one direction per line");
  result_.vectorName = shape.vectorName;
  result_.channelNames = shape.channelNames;
  result_.periodic = shape.periodic;
  result_.withVorticity = shape.withVorticity;
  result_.steps.assign(lineCount(), 0);
  result_.reasons.assign(lineCount(), AMRSTREAM_REASON_RUNNING);
}

void TraceAccumulator::add(RoundBlock&& round) {
  const std::size_t channels = result_.channelCount();
  std::uint64_t points = 0;
  for (const shared::LineRound& r : round.lines) points += r.points;
  if (round.positions.size() != points || round.times.size() != points ||
      round.vectors.size() != points || round.channels.size() != points * channels ||
      round.vorticity.size() != (result_.withVorticity ? points : 0))
    throw std::invalid_argument("TraceAccumulator: a round's arrays do not match its lines");

  const std::uint64_t bytes =
      (points_ + points) * TraceSet::bytesPerPoint(channels, result_.withVorticity);
  if (maxBytes_ > 0 && bytes > maxBytes_)
    throw InputError("traces", fmt::format("the traces grew past {:.1f} GiB, the limit for this "
                                           "machine, with {} of {} lines finished; trace fewer "
                                           "seeds or steps, or use --endpoints-only",
                                           double(maxBytes_) / 0x1p30, finished_, lineCount()));

  StoredRound stored{std::move(round), {}};
  stored.destinations.resize(stored.block.lines.size());
  for (std::size_t i = 0; i < stored.block.lines.size(); ++i) {
    const shared::LineRound& r = stored.block.lines[i];
    if (r.line >= lineCount()) throw std::invalid_argument("TraceAccumulator: no such line");
    stored.destinations[i] = pointsPerLine_[r.line];  // offsets[line] is added when gathering
    pointsPerLine_[r.line] += r.points;
    result_.steps[r.line] = r.steps;
    if (r.reason != AMRSTREAM_REASON_RUNNING) {
      result_.reasons[r.line] = r.reason;
      ++finished_;
    }
  }
  points_ += points;
  rounds_.push_back(std::move(stored));
}

template <typename Rounds>
TraceSet TraceAccumulator::gatherAll(const TraceAccumulator& from, Rounds& rounds, bool release) {
  TraceSet out = from.result_;
  out.seedIds = from.layout_.seedIds;
  out.directions = from.layout_.directions;
  out.offsets.assign(from.pointsPerLine_.size() + 1, 0);
  for (std::size_t line = 0; line < from.pointsPerLine_.size(); ++line)
    out.offsets[line + 1] = out.offsets[line] + from.pointsPerLine_[line];
  const std::uint64_t points = out.pointCount();
  const std::vector<std::uint64_t>& at = out.offsets;
  gather(out.positions, points, 1, rounds, &RoundBlock::positions, at, release);
  gather(out.times, points, 1, rounds, &RoundBlock::times, at, release);
  gather(out.vectors, points, 1, rounds, &RoundBlock::vectors, at, release);
  gather(out.channels, points, out.channelCount(), rounds, &RoundBlock::channels, at, release);
  if (out.withVorticity)
    gather(out.vorticity, points, 1, rounds, &RoundBlock::vorticity, at, release);
  return out;
}

TraceSet TraceAccumulator::snapshot() const { return gatherAll(*this, rounds_, false); }

TraceSet TraceAccumulator::assemble() {
  TraceSet out = gatherAll(*this, rounds_, true);
  const std::uint64_t limit = maxBytes_;
  *this = TraceAccumulator(LineLayout{}, out);
  maxBytes_ = limit;
  return out;
}

}  // namespace amrstream::flow
