#include "gathered_traces.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

namespace amrstream::mpi {

GatheredTraces::GatheredTraces(std::vector<flow::TraceSet> parts) : parts_(std::move(parts)) {
  if (parts_.empty()) parts_.emplace_back();
  lines_ = flow::shapeOf(parts_.front());

  for (std::uint32_t p = 0; p < parts_.size(); ++p) {
    views_.emplace_back(parts_[p]);
    for (std::uint64_t line = 0; line < parts_[p].lineCount(); ++line)
      sources_.push_back({p, line});
  }
  const auto key = [&](const Source& s) {
    const flow::TraceSet& t = parts_[s.part];
    return std::tuple(t.directions[s.line] < 0.0f, t.seedIds[s.line]);
  };
  std::ranges::sort(sources_, [&](const Source& a, const Source& b) { return key(a) < key(b); });
  for (std::size_t i = 1; i < sources_.size(); ++i)
    if (key(sources_[i - 1]) == key(sources_[i]))
      throw std::invalid_argument("gathered traces: two lines of seed " +
                                  std::to_string(std::get<1>(key(sources_[i]))) +
                                  " in one direction");

  for (const Source& s : sources_) {
    const flow::TraceSet& t = parts_[s.part];
    lines_.seedIds.push_back(t.seedIds[s.line]);
    lines_.directions.push_back(t.directions[s.line]);
    lines_.steps.push_back(t.steps[s.line]);
    lines_.reasons.push_back(t.reasons[s.line]);
    lines_.offsets.push_back(lines_.offsets.back() + t.pointCount(s.line));
  }
}

std::span<const float> GatheredTraces::column(flow::PointColumn column, std::size_t line,
                                              std::vector<float>& scratch) const {
  const Source& s = sources_[line];
  return views_[s.part].column(column, s.line, scratch);
}

}  // namespace amrstream::mpi
