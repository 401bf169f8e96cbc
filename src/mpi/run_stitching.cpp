#include "run_stitching.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

#include "../../shaders/glsl/shared/trace_codes.h"

namespace amrstream::mpi {

namespace {

struct RunAt {
  std::uint32_t part;
  std::size_t run;
};

template <typename Column>
void appendRange(Column& to, const Column& from, std::uint64_t first, std::uint64_t count,
                 std::size_t width = 1) {
  if (from.empty()) return;
  to.insert(to.end(), from.begin() + std::ptrdiff_t(first * width),
            from.begin() + std::ptrdiff_t((first + count) * width));
}

// Run r of `from`'s points after `to`'s.
void appendPoints(flow::TraceSet& to, const flow::TraceSet& from, std::size_t r) {
  const std::uint64_t first = from.firstPoint(r), count = from.pointCount(r);
  appendRange(to.positions, from.positions, first, count);
  appendRange(to.positionsLow, from.positionsLow, first, count);
  appendRange(to.times, from.times, first, count);
  appendRange(to.vectors, from.vectors, first, count);
  appendRange(to.channels, from.channels, first, count, from.channelCount());
  appendRange(to.vorticity, from.vorticity, first, count);
}

}  // namespace

LineRange pieceLines(std::size_t lines, int rank, int ranks) {
  const auto edge = [&](int k) {
    return static_cast<std::uint32_t>(lines * std::size_t(k) / std::size_t(ranks));
  };
  return {edge(rank), edge(rank + 1)};
}

std::vector<flow::TraceSet> runsByPiece(const flow::TraceSet& runs, std::size_t lines, int ranks) {
  std::vector<flow::TraceSet> pieces(std::size_t(ranks), flow::shapeOf(runs));
  std::vector<std::uint32_t> lasts;  // of each rank's lines
  for (int k = 0; k < ranks; ++k) lasts.push_back(pieceLines(lines, k, ranks).last);
  for (std::size_t r = 0; r < runs.lineCount(); ++r) {
    const auto holder = std::ranges::upper_bound(lasts, runs.seedIds[r]);
    if (holder == lasts.end())
      throw std::runtime_error("a run of line " + std::to_string(runs.seedIds[r]) + " of " +
                               std::to_string(lines));
    flow::TraceSet& piece = pieces[std::size_t(holder - lasts.begin())];
    piece.seedIds.push_back(runs.seedIds[r]);
    piece.directions.push_back(runs.directions[r]);
    piece.steps.push_back(runs.steps[r]);
    piece.reasons.push_back(runs.reasons[r]);
    appendPoints(piece, runs, r);
    piece.offsets.push_back(piece.positions.size());
  }
  return pieces;
}

flow::TraceSet stitchRuns(std::vector<flow::TraceSet> parts, const flow::LineLayout& layout,
                          LineRange range) {
  if (parts.empty()) return {};
  const flow::TraceSet& shape = parts.front();
  flow::TraceSet lines = flow::shapeOf(shape);

  std::vector<RunAt> runs;
  for (std::uint32_t p = 0; p < parts.size(); ++p)
    for (std::size_t r = 0; r < parts[p].lineCount(); ++r) runs.push_back({p, r});
  // A line's runs by its steps at their ends; a run that ended the line after none more steps
  // than the run before it comes last.
  const auto key = [&](const RunAt& at) {
    const flow::TraceSet& t = parts[at.part];
    return std::tuple(t.seedIds[at.run], t.steps[at.run],
                      t.reasons[at.run] != AMRSTREAM_REASON_RUNNING);
  };
  std::ranges::sort(runs, [&](const RunAt& a, const RunAt& b) { return key(a) < key(b); });

  std::size_t at = 0;
  for (std::uint32_t line = range.first; line < range.last; ++line) {
    if (at == runs.size() || parts[runs[at].part].seedIds[runs[at].run] != line)
      throw std::runtime_error("line " + std::to_string(line) + " was traced by no rank");
    std::int32_t reason = AMRSTREAM_REASON_RUNNING;
    std::uint32_t steps = 0;
    for (; at < runs.size() && parts[runs[at].part].seedIds[runs[at].run] == line; ++at) {
      const flow::TraceSet& t = parts[runs[at].part];
      const std::size_t r = runs[at].run;
      if (reason != AMRSTREAM_REASON_RUNNING)
        throw std::runtime_error("line " + std::to_string(line) + " goes on after its end");
      appendPoints(lines, t, r);
      reason = t.reasons[r];
      steps = t.steps[r];
    }
    if (reason == AMRSTREAM_REASON_RUNNING)
      throw std::runtime_error("line " + std::to_string(line) + " has no end");
    lines.seedIds.push_back(layout.seedIds[line]);
    lines.directions.push_back(layout.directions[line]);
    lines.steps.push_back(steps);
    lines.reasons.push_back(reason);
    lines.offsets.push_back(lines.positions.size());
  }
  if (at != runs.size()) throw std::runtime_error("runs of lines beyond the last line");
  return lines;
}

}  // namespace amrstream::mpi
