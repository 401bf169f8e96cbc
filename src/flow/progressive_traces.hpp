#pragma once
// Traces that grow a few steps at a time, for the viewer's progressive tracing: each advance()
// continues every running trace from its last point for up to N more steps, through any tracer
// (the CPU reference or a GPU backend, one thread per running particle). RK4 keeps no state
// between steps but the point, so the traces equal one run of maxSteps, up to the rounding of
// the stored float end points; IntegrationTime and the remaining --max-length carry over.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

#include "integrator.hpp"
#include "trace_set.hpp"

namespace amrstream::flow {

using TraceFunction =
    std::function<TraceSet(std::span<const glm::dvec3> seeds, const TraceOptions& options)>;

class ProgressiveTraces {
 public:
  // options.keepHistory must be true.
  ProgressiveTraces(std::span<const glm::dvec3> seeds, const TraceOptions& options,
                    std::string vectorName);

  // Advances the running traces by up to `steps` steps each; returns the particle-steps taken.
  std::size_t advance(const TraceFunction& trace, std::uint32_t steps);

  bool finished() const { return running_.empty(); }
  std::size_t runningCount() const { return running_.size(); }
  std::size_t stepsTaken() const { return stepsTaken_; }
  // Reasons are AMRSTREAM_REASON_RUNNING until a trace ends; capacity is maxSteps + 1.
  const TraceSet& traces() const { return traces_; }

 private:
  TraceOptions options_;
  std::vector<glm::dvec3> seeds_;
  std::uint32_t roundSteps_ = 0;         // steps every running trace has taken
  TraceSet traces_;
  std::vector<std::uint32_t> running_;  // seeds of the traces still running
  std::vector<float> lengths_;          // physical arc length so far, per seed
  std::size_t stepsTaken_ = 0;
};

}  // namespace amrstream::flow
