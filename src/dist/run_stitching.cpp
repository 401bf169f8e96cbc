#include "run_stitching.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

#include "../../shaders/glsl/shared/trace_codes.h"

namespace amrstream::dist {

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

}  // namespace

flow::TraceSet stitchRuns(std::vector<flow::TraceSet> parts, const flow::LineLayout& layout) {
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

  const std::size_t channels = shape.channelCount();
  std::size_t at = 0;
  for (std::uint32_t line = 0; line < layout.seedIds.size(); ++line) {
    if (at == runs.size() || parts[runs[at].part].seedIds[runs[at].run] != line)
      throw std::runtime_error("line " + std::to_string(line) + " was traced by no rank");
    std::int32_t reason = AMRSTREAM_REASON_RUNNING;
    std::uint32_t steps = 0;
    for (; at < runs.size() && parts[runs[at].part].seedIds[runs[at].run] == line; ++at) {
      const flow::TraceSet& t = parts[runs[at].part];
      const std::size_t r = runs[at].run;
      if (reason != AMRSTREAM_REASON_RUNNING)
        throw std::runtime_error("line " + std::to_string(line) + " goes on after its end");
      const std::uint64_t first = t.firstPoint(r), count = t.pointCount(r);
      appendRange(lines.positions, t.positions, first, count);
      appendRange(lines.positionsLow, t.positionsLow, first, count);
      appendRange(lines.times, t.times, first, count);
      appendRange(lines.vectors, t.vectors, first, count);
      appendRange(lines.channels, t.channels, first, count, channels);
      appendRange(lines.vorticity, t.vorticity, first, count);
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

}  // namespace amrstream::dist
