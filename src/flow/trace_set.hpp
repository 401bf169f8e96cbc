#pragma once
// The result of tracing: for each seed a polyline of up to `capacity` points (the seed and one
// point per step), stored seed-major with a fixed stride, plus per-trace counts and reasons.
// Without history (endpoints-only) capacity is 1 and each trace stores only its last point.

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace amrstream::flow {

struct TraceSet {
  // Bytes stored per trace point: position, IntegrationTime and vector.
  static constexpr std::size_t kBytesPerPoint = 2 * sizeof(glm::vec3) + sizeof(float);

  std::uint32_t seedCount = 0;
  std::uint32_t capacity = 0;  // points stored per trace: max steps + 1, or 1 without history
  std::string vectorName;      // name of the traced vector, e.g. "velocity" or "velx,vely,velz"
  std::vector<glm::vec3> positions;        // physical coordinates, [seed * capacity + point]
  std::vector<float> times;                // IntegrationTime at each point
  std::vector<glm::vec3> vectors;          // sampled vector at each point
  std::vector<std::uint32_t> pointCounts;  // points stored for each trace, >= 1
  std::vector<std::uint32_t> steps;        // integration steps each trace took
  std::vector<std::int32_t> reasons;       // ReasonForTermination of each trace (trace_codes.h)

  void resize(std::uint32_t seeds, std::uint32_t pointsPerTrace) {
    seedCount = seeds;
    capacity = pointsPerTrace;
    const std::size_t n = std::size_t(seeds) * pointsPerTrace;
    positions.assign(n, glm::vec3(0.0f));
    times.assign(n, 0.0f);
    vectors.assign(n, glm::vec3(0.0f));
    pointCounts.assign(seeds, 0);
    steps.assign(seeds, 0);
    reasons.assign(seeds, 0);
  }
  std::size_t at(std::uint32_t seed, std::uint32_t point) const {
    return std::size_t(seed) * capacity + point;
  }
};

}  // namespace amrstream::flow
