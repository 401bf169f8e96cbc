#pragma once
// The deep hierarchy the tests trace: a nest of 28 levels (cells 1 to 2^27 finest cells wide) in a
// domain of 2^30 finest cells per axis (8 root cells, cubes of 4 cells), whose finest cells lie
// 2^27 to 2^28 finest cells from the domain's middle, where float32 cell units (centred there)
// are 16 to 32 finest cells apart; and seeds a few finest cells from the nest's centre, whose
// traces circle it and spiral out across the finest levels.

#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::testing {

bricks::AmrField deepNest();
// Physical coordinates.
std::vector<glm::dvec3> deepNestSeeds(const bricks::AmrField& nest);

}  // namespace amrstream::testing
