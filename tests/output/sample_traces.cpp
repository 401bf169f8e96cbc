#include "sample_traces.hpp"

#include <limits>

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

flow::TraceSet sampleTraces(const std::vector<std::uint32_t>& pointCounts, std::uint32_t capacity,
                            const char* vectorName) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  flow::TraceSet traces;
  traces.resize(static_cast<std::uint32_t>(pointCounts.size()), capacity);
  traces.vectorName = vectorName;
  for (std::uint32_t seed = 0; seed < traces.seedCount; ++seed) {
    traces.pointCounts[seed] = pointCounts[seed];
    traces.reasons[seed] = sampleReason(seed);
    for (std::uint32_t point = 0; point < capacity; ++point) {
      const bool valid = point < pointCounts[seed];
      const std::size_t i = traces.at(seed, point);
      traces.positions[i] = valid ? samplePosition(seed, point) : glm::vec3(nan);
      traces.times[i] = valid ? sampleTime(seed, point) : nan;
      traces.vectors[i] = valid ? sampleVector(seed, point) : glm::vec3(nan);
    }
  }
  return traces;
}

}  // namespace amrstream::testing
