#pragma once
// Point location and basis-function reconstruction (DESIGN.md section 5): the CPU reference of
// the GLSL functions of the same names.

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>

#include "vector_volume.hpp"

namespace amrstream::flow {

// A sample whose weights sum to no more than this is invalid.
inline constexpr float kMinWeightSum = AMRSTREAM_MIN_WEIGHT_SUM;

struct VectorSample {
  bool located = false;  // p is inside the domain and in a region
  bool valid = false;    // located and the weights sum above kMinWeightSum
  glm::vec3 value{0.0f};
  float cellWidth = 0.0f;  // finest cell width of p's region, in finest-cell units
};

// Region containing p (finest-cell units), or -1 outside the domain or in empty space.
std::int32_t locateRegion(const VectorVolume& volume, glm::vec3 p);

// The region of a trace's previous sample. Consecutive samples mostly share a region, and
// regions are disjoint half-open boxes, so a point inside the domain and inside that box is in
// that region: testing it first gives locateRegion()'s answer without the tree descent.
struct RegionCache {
  std::int32_t id = -1;
};

// With a cache, tries its region first and stores the region found.
VectorSample sampleVector(const VectorVolume& volume, glm::vec3 p, RegionCache* cache = nullptr);

// The same reconstruction for a scalar gathered in brick order (gatherScalar()): the value at p,
// or none outside the domain and regions, where the weights vanish, or when it is not finite.
std::optional<float> sampleScalar(const VectorVolume& volume, std::span<const float> scalars,
                                  glm::vec3 p, RegionCache* cache = nullptr);

}  // namespace amrstream::flow
