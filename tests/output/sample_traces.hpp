#pragma once
// Hand-built TraceSets with known contents, shared by the writer tests and write_sample_vtp.

#include <cstdint>
#include <vector>

#include "flow/trace_set.hpp"

namespace amrstream::testing {

// Trace s has pointCounts[s] valid points (each <= capacity). Point p of trace s sits at
// samplePosition(s, p) with time sampleTime(s, p) and vector sampleVector(s, p); the slots past
// a trace's end hold NaN so a writer that copies them is caught.
flow::TraceSet sampleTraces(const std::vector<std::uint32_t>& pointCounts, std::uint32_t capacity,
                            const char* vectorName = "velocity");

glm::vec3 samplePosition(std::uint32_t seed, std::uint32_t point);
float sampleTime(std::uint32_t seed, std::uint32_t point);
glm::vec3 sampleVector(std::uint32_t seed, std::uint32_t point);
std::int32_t sampleReason(std::uint32_t seed);

// The set write_sample_vtp writes: 4 traces of 3, 1, 5 and 2 points, capacity 5.
inline const std::vector<std::uint32_t> kSamplePointCounts{3, 1, 5, 2};
inline constexpr std::uint32_t kSampleCapacity = 5;

}  // namespace amrstream::testing
