#include "sample_traces.hpp"

#include "shaders/glsl/shared/trace_codes.h"

namespace amrstream::testing {

// Values exact in float, distinct per trace and point; sampleVector(0, 0) is (3, 4, 0), speed 5,
// and sampleVector(1, 0) is zero, speed 0.
glm::vec3 samplePosition(std::uint32_t seed, std::uint32_t point) {
  return {seed + 0.25f * point, -2.0f * seed + 0.5f * point, 0.125f * seed * point + 1.0f};
}

float sampleTime(std::uint32_t seed, std::uint32_t point) { return 0.5f * point + seed / 8.0f; }

glm::vec3 sampleVector(std::uint32_t seed, std::uint32_t point) {
  if (seed == 0 && point == 0) return {3.0f, 4.0f, 0.0f};
  if (seed == 1 && point == 0) return glm::vec3(0.0f);
  return {1.5f * point - seed, -0.75f * seed, 2.0f + point};
}

std::int32_t sampleReason(std::uint32_t seed) {
  static const std::int32_t reasons[] = {AMRSTREAM_REASON_OUT_OF_DOMAIN, AMRSTREAM_REASON_MAX_STEPS,
                                         AMRSTREAM_REASON_STAGNATION, AMRSTREAM_REASON_MAX_LENGTH,
                                         AMRSTREAM_REASON_UNEXPECTED_VALUE};
  return reasons[seed % std::size(reasons)];
}

flow::TraceSet sampleTraces(const std::vector<std::uint32_t>& pointCounts, const char* vectorName) {
  flow::TraceSet traces;
  traces.vectorName = vectorName;
  for (std::uint32_t line = 0; line < pointCounts.size(); ++line) {
    traces.seedIds.push_back(line);
    traces.directions.push_back(1.0f);
    traces.steps.push_back(pointCounts[line] == 0 ? 0 : pointCounts[line] - 1);
    traces.reasons.push_back(sampleReason(line));
    traces.offsets.push_back(traces.offsets.back() + pointCounts[line]);
    for (std::uint32_t point = 0; point < pointCounts[line]; ++point) {
      traces.positions.push_back(samplePosition(line, point));
      traces.times.push_back(sampleTime(line, point));
      traces.vectors.push_back(sampleVector(line, point));
    }
  }
  return traces;
}

glm::dvec3 precisePosition(std::uint32_t seed, std::uint32_t point) {
  return {0.37123456789012345 + 1e-9 * point, 0.5 - 1e-9 * point - 1e-7 * seed,
          0.25 + 1e-11 * seed * point};
}

flow::TraceSet preciseSampleTraces(const std::vector<std::uint32_t>& pointCounts,
                                   const char* vectorName) {
  flow::TraceSet traces = sampleTraces(pointCounts, vectorName);
  traces.precisePositions = true;
  traces.positionsLow.resize(traces.pointCount());
  for (std::uint32_t line = 0; line < pointCounts.size(); ++line)
    for (std::uint32_t point = 0; point < pointCounts[line]; ++point) {
      const flow::SplitPosition split = flow::splitPosition(precisePosition(line, point));
      traces.positions[at(traces, line, point)] = split.high;
      traces.positionsLow[at(traces, line, point)] = split.low;
    }
  return traces;
}

glm::dvec3 exactPosition(const flow::TraceSet& traces, std::uint64_t point) {
  if (!traces.precisePositions) return glm::dvec3(traces.positions[point]);
  return flow::joinPosition(traces.positions[point], traces.positionsLow[point]);
}

}  // namespace amrstream::testing
