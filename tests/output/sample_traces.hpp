#pragma once
// Hand-built TraceSets with known contents, shared by the writer tests and write_sample_vtp.

#include <cstdint>
#include <vector>

#include "flow/trace_set.hpp"

namespace amrstream::testing {

// Line s (seed s, forward) has pointCounts[s] points. Point p of line s sits at
// samplePosition(s, p) with time sampleTime(s, p) and vector sampleVector(s, p).
flow::TraceSet sampleTraces(const std::vector<std::uint32_t>& pointCounts,
                            const char* vectorName = "velocity");

glm::vec3 samplePosition(std::uint32_t seed, std::uint32_t point);
float sampleTime(std::uint32_t seed, std::uint32_t point);
glm::vec3 sampleVector(std::uint32_t seed, std::uint32_t point);
std::int32_t sampleReason(std::uint32_t seed);

// A position float32 cannot resolve: the points of a line lie 1e-9 apart around 0.3712, where
// float32 positions are 3e-8 apart.
glm::dvec3 precisePosition(std::uint32_t seed, std::uint32_t point);
// sampleTraces with precise positions: point p of line s split from precisePosition(s, p).
flow::TraceSet preciseSampleTraces(const std::vector<std::uint32_t>& pointCounts,
                                   const char* vectorName = "velocity");
// Point i's position: joinPosition of its parts when precise, else the stored float.
glm::dvec3 exactPosition(const flow::TraceSet& traces, std::uint64_t point);

// The set write_sample_vtp writes: 4 lines of 3, 1, 5 and 2 points.
inline const std::vector<std::uint32_t> kSamplePointCounts{3, 1, 5, 2};

}  // namespace amrstream::testing

namespace amrstream::testing {

// The number of points of every line.
inline std::vector<std::uint32_t> pointCountsOf(const flow::TraceSet& traces) {
  std::vector<std::uint32_t> counts;
  for (std::size_t line = 0; line < traces.lineCount(); ++line)
    counts.push_back(static_cast<std::uint32_t>(traces.pointCount(line)));
  return counts;
}

// The index of point p of a line.
inline std::uint64_t at(const flow::TraceSet& traces, std::size_t line, std::uint64_t p) {
  return traces.firstPoint(line) + p;
}

}  // namespace amrstream::testing
