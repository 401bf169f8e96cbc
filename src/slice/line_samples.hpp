#pragma once
// The reconstruction along a slice's field lines: the vector and every point-data channel at each
// of their points, for the lines' colours and widths and their .vtp.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "even_lines.hpp"
#include "flow/vector_volume.hpp"
#include "slice_plane.hpp"

namespace amrstream::slice {

struct LineSamples {
  // The points of all lines in order; line i has points [offsets[i], offsets[i + 1]).
  std::vector<std::uint64_t> offsets{0};
  std::vector<glm::dvec3> positions;  // physical
  std::vector<glm::vec3> vectors;     // NaN where the point has no valid sample
  std::vector<float> channels;        // channelCount() per point, NaN likewise
};

// On all cores. The reconstruction at plane.physical(p) for every point p, as the lines follow it.
LineSamples sampleAlongLines(const flow::VectorVolume& volume, const SlicePlane& plane,
                             const std::vector<PlaneLine>& lines);

// Per line, per point: channel `channel` of the samples (of `channelCount`), or the vector's
// length where `channel` is negative.
std::vector<std::vector<float>> valuesAlongLines(const LineSamples& samples,
                                                 std::size_t channelCount, int channel);

}  // namespace amrstream::slice
