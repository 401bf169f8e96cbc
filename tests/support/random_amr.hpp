#pragma once
// Random multi-level AMR layouts for tests: coarsest cells on a root grid, each refined into 8
// children with a given probability, recursively down to level 0. Such layouts have level jumps
// of more than one across faces and refined cells touching the domain boundary.

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>

#include "bricks/amr_field.hpp"

namespace amrstream::testing {

struct RandomAmrOptions {
  int levels = 4;                   // levels 0 .. levels-1
  glm::ivec3 rootCells{3, 3, 3};    // coarsest cells per axis
  double refineProbability = 0.45;  // chance that a cell above level 0 is split
  glm::ivec3 origin{0};  // lower corner, in finest cells (multiple of the coarsest width)
};

// Channel values of a cell as a function of its centre in finest-cell units.
using VectorFunction = std::function<glm::vec3(glm::dvec3 centre)>;

// Channels "vx", "vy", "vz" from `field`; uniform random values in [-1, 1] when field is empty.
bricks::AmrField randomAmr(std::uint64_t seed, const RandomAmrOptions& options = {},
                           const VectorFunction& field = {});

}  // namespace amrstream::testing
