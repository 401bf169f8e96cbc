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

}  // namespace amrstream::testing
