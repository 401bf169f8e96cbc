#pragma once
// The deep hierarchies the tests trace, both 2^30 finest cells per axis, with seeds a few finest
// cells from the nest's centre, whose traces circle it and spiral out across the finest levels.
//
// deepNest(): 28 levels (cells 1 to 2^27 finest cells wide; 8 root cells, cubes of 4 cells,
// proper nesting), whose finest cells lie 2^27 to 2^28 finest cells from the domain's middle,
// where float32 cell units (centred there) are 16 to 32 finest cells apart.
//
// deepOctreeNest(): 30 levels, an octree refined towards its centre (2 root cells, cubes of 2
// cells), the centre about 2^27.4 finest cells from the middle (float32 units 16 cells apart).
// Every level's cells touch cells of the coarser levels, whose tents reach the centre: the
// spiral's speed is capped at 8 finest cells times its rotation rate, so the coarse cells bend
// the traces without throwing them out of the finest levels. The centre's coordinates have
// alternating bits (1/3, 2/3, 2/5 of the domain), so each level's cube holds it a third of the
// cube's width or more from its faces, and the seeds start among the finest levels.

#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::testing {

struct DeepNest {
  bricks::AmrField field;
  std::vector<glm::dvec3> seeds;  // physical coordinates
};

DeepNest deepNest();
DeepNest deepOctreeNest();

}  // namespace amrstream::testing
