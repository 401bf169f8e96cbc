#pragma once
// Point location and basis-function reconstruction (docs/architecture.md, "Sampling"): the CPU
// reference of the GLSL functions of the same names (shaders/glsl/include/sampler.glsl and
// point_data.glsl).

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>

#include "cell_point.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

// A sample whose weights sum to no more than this is invalid.
inline constexpr float kMinWeightSum = AMRSTREAM_MIN_WEIGHT_SUM;

struct VectorSample {
  bool located = false;  // p is inside the domain and in a region
  bool valid = false;    // located and the weights sum above kMinWeightSum
  glm::vec3 value{0.0f};
  float cellWidth = 0.0f;    // finest cell width of p's region, in finest-cell units
  std::int32_t region = -1;  // p's region when located
};

// p moved by a whole period into the domain along its periodic axes (its anchor shifted, so
// exactly); unchanged otherwise.
CellPoint wrapPeriodic(const VectorVolume& volume, CellPoint p);

// Region containing p, or -1 outside the domain or in empty space.
std::int32_t locateRegion(const VectorVolume& volume, const CellPoint& p);

// The region of a trace's previous sample. Consecutive samples mostly share a region, and
// regions are disjoint half-open boxes, so a point inside the domain and inside that box is in
// that region: testing it first gives locateRegion()'s answer without the tree descent.
struct RegionCache {
  std::int32_t id = -1;
};

// p must already be wrapped (wrapPeriodic). With a cache, tries its region first and stores the
// region found.
VectorSample sampleVector(const VectorVolume& volume, const CellPoint& p,
                          RegionCache* cache = nullptr);

// The same reconstruction for a scalar gathered in brick order (gatherScalar()): the value at p,
// or none outside the domain and regions, where the weights vanish, or when it is not finite.
// With `gradients` (cellGradients() of the scalars) each cell contributes its linear model
// instead of its value: the linear interpolant.
std::optional<float> sampleScalar(const VectorVolume& volume, std::span<const float> scalars,
                                  const CellPoint& p, RegionCache* cache = nullptr,
                                  std::span<const glm::vec3> gradients = {});

// The point-data channels at p in `region` (where p's vector sample was located): one value per
// channel into `out`, NaN for all when region is -1 or the weights vanish.
void sampleChannels(const VectorVolume& volume, std::int32_t region, const CellPoint& p,
                    std::span<float> out);

// The curl of the reconstructed vector at p in `region`, in the vector's units per physical
// length; NaN when region is -1 or the weights vanish. The reconstruction is a quotient of tent
// sums, B = S_v / S_1, so dB/dp = (dS_v/dp - B dS_1/dp) / S_1 with the tents' piecewise-constant
// derivatives; with the linear interpolant v_i is the cell's model v_i + G_i (p - c_i), whose
// own derivative G_i adds S_G / S_1.
glm::vec3 sampleVorticity(const VectorVolume& volume, std::int32_t region, const CellPoint& p);

}  // namespace amrstream::flow
