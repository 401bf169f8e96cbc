#pragma once
// The reconstructed field on a uniform grid of points, as ParaView's Resample To Image makes it:
// the vector and the point-data channels sampled (tent or linear interpolant, as the volume says)
// at the centres of NX x NY x NZ equal cells of a box, with a mask of the points where the
// sample is valid (inside the domain, in a region, weights above kMinWeightSum).

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "vector_volume.hpp"

namespace amrstream::flow {

struct UniformGridSpec {
  glm::dvec3 lower{0.0}, upper{1.0};  // physical box
  std::array<std::uint32_t, 3> dims{1, 1, 1};

  glm::dvec3 spacing() const {
    return (upper - lower) / glm::dvec3(dims[0], dims[1], dims[2]);
  }
  glm::dvec3 origin() const { return lower + 0.5 * spacing(); }  // the first point
  std::uint64_t pointCount() const { return std::uint64_t(dims[0]) * dims[1] * dims[2]; }
};

struct UniformGrid {
  UniformGridSpec spec;
  // x fastest: point (i, j, k) is i + NX (j + NY k). Invalid points hold zeros.
  std::vector<glm::vec3> vectors;
  std::vector<float> channels;  // interleaved: channel c of point n at n * channelCount + c
  std::vector<std::uint8_t> valid;
  std::uint64_t validCount = 0;
};

// Samples `volume` at every point of `spec` on all cores; `progress(done)` is called from one
// thread at a time with the number of rows of points done (of dims[1] * dims[2]).
UniformGrid resampleUniform(const VectorVolume& volume, const UniformGridSpec& spec,
                            const std::function<void(std::size_t)>& progress = {});

}  // namespace amrstream::flow
