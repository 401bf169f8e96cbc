#include "progressive_traces.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace amrstream::flow {

ProgressiveTraces::ProgressiveTraces(std::span<const glm::dvec3> seeds, const TraceOptions& options,
                                     std::string vectorName)
    : options_(options), seeds_(seeds.begin(), seeds.end()), running_(seeds.size()),
      lengths_(seeds.size(), 0.0f) {
  if (!options.keepHistory)
    throw std::invalid_argument("ProgressiveTraces: traces grow only with history");
  traces_.resize(static_cast<std::uint32_t>(seeds.size()), options.maxSteps + 1);
  traces_.vectorName = std::move(vectorName);
  std::iota(running_.begin(), running_.end(), 0u);
}

std::size_t ProgressiveTraces::advance(const TraceFunction& trace, std::uint32_t steps) {
  if (running_.empty() || steps == 0) return 0;
  std::vector<glm::dvec3> starts(running_.size());
  for (std::size_t i = 0; i < running_.size(); ++i) {
    const std::uint32_t s = running_[i];
    const std::uint32_t n = traces_.pointCounts[s];
    starts[i] = n == 0 ? seeds_[s] : glm::dvec3(traces_.positions[traces_.at(s, n - 1)]);
  }
  TraceOptions chunkOptions = options_;
  chunkOptions.maxSteps = std::min(steps, options_.maxSteps - roundSteps_);
  chunkOptions.maxLength = 0.0f;  // enforced below, over the whole trace
  const TraceSet chunk = trace(starts, chunkOptions);
  roundSteps_ += chunkOptions.maxSteps;

  std::size_t taken = 0;
  std::vector<std::uint32_t> stillRunning;
  for (std::size_t i = 0; i < running_.size(); ++i) {
    const std::uint32_t s = running_[i];
    const std::uint32_t first = traces_.pointCounts[s] == 0 ? 0 : 1;  // later chunks repeat their start
    const float timeOffset =
        traces_.pointCounts[s] == 0 ? 0.0f : traces_.times[traces_.at(s, traces_.pointCounts[s] - 1)];
    std::int32_t reason = chunk.reasons[i];
    for (std::uint32_t p = first; p < chunk.pointCounts[i]; ++p) {
      const std::size_t from = chunk.at(static_cast<std::uint32_t>(i), p);
      const std::uint32_t n = traces_.pointCounts[s];
      if (n > 0 && options_.maxLength > 0.0f) {
        const float step = glm::length(chunk.positions[from] - traces_.positions[traces_.at(s, n - 1)]);
        if (lengths_[s] + step > options_.maxLength) {
          reason = AMRSTREAM_REASON_MAX_LENGTH;
          break;
        }
        lengths_[s] += step;
      }
      const std::size_t to = traces_.at(s, n);
      traces_.positions[to] = chunk.positions[from];
      traces_.times[to] = timeOffset + chunk.times[from];
      traces_.vectors[to] = chunk.vectors[from];
      ++traces_.pointCounts[s];
      if (n > 0) {
        ++traces_.steps[s];
        ++taken;
      }
    }
    if (reason == AMRSTREAM_REASON_MAX_STEPS && roundSteps_ < options_.maxSteps)
      stillRunning.push_back(s);
    else
      traces_.reasons[s] = reason;
  }
  running_ = std::move(stillRunning);
  stepsTaken_ += taken;
  return taken;
}

}  // namespace amrstream::flow
