#pragma once
// Small datasets with known vector fields for the sampler and integrator tests.

#include "flow/vector_volume.hpp"
#include "random_amr.hpp"

namespace amrstream::testing {

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
