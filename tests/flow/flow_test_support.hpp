#pragma once
// Small datasets with known vector fields for the sampler and integrator tests.

#include <cstdint>
#include <random>
#include <vector>

#include "flow/vector_volume.hpp"
#include "random_amr.hpp"

namespace amrstream::testing {

// `count` points uniform in [lower - around, upper + around), then points on, just inside and
// just outside each face of [lower, upper) (by 1e-12, 2^-21, 2^-20 and 1e-3 cells), where
// lookups that round to float decide differently.
inline std::vector<glm::dvec3> pointsInAndAroundBox(glm::dvec3 lower, glm::dvec3 upper,
                                                    double around, int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<glm::dvec3> points;
  for (int n = 0; n < count; ++n)
    points.push_back(lower - around +
                     glm::dvec3(unit(rng), unit(rng), unit(rng)) * (upper - lower + 2.0 * around));
  for (const double in : {0.0, 1e-12, 0x1.0p-21, 0x1.0p-20, 1e-3, -1e-12})
    for (int axis = 0; axis < 3; ++axis) {
      glm::dvec3 nearUpper = (lower + upper) / 2.0, nearLower = nearUpper;
      nearUpper[axis] = upper[axis] - in;
      nearLower[axis] = lower[axis] + in;
      points.push_back(nearUpper);
      points.push_back(nearLower);
    }
  return points;
}

inline flow::VectorVolume volumeOf(const bricks::AmrField& field) {
  return flow::buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"});
}

// An n^3 grid of level-0 cells at the origin with the given field.
inline bricks::AmrField uniformGrid(int n, const VectorFunction& f) {
  RandomAmrOptions options;
  options.levels = 1;
  options.rootCells = glm::ivec3(n);
  return randomAmr(0, options, f);
}

// Two 4^3 blocks of level-0 cells, at x = 0..4 and x = 8..12, with the constant vector (1, 1, 1).
// The second block's domain starts at x = 7.5, where all its tent functions are zero; the gap
// between the domains, 4.5 <= x < 7.5, is in no region.
inline bricks::AmrField twoBlocksWithAGap() {
  std::vector<glm::ivec3> lowers;
  for (int block : {0, 8})
    for (int z = 0; z < 4; ++z)
      for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) lowers.push_back(glm::ivec3(block + x, y, z));
  std::vector<float> ones(lowers.size(), 1.0f);
  return bricks::AmrField(lowers, std::vector<std::uint8_t>(lowers.size(), 0),
                          {{"vx", ones}, {"vy", ones}, {"vz", ones}}, {}, "two-blocks");
}

}  // namespace amrstream::testing
