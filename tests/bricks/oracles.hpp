#pragma once
// Brute-force checks of brick and region sets, shared by the builder tests.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "bricks/brick_builder.hpp"
#include "bricks/region_builder.hpp"

namespace amrstream::testing {

// A field with one channel "id" holding each cell's index.
bricks::AmrField makeField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels);

// Level-0 cells at the origin and at 2^k along each axis, k = 0..19: sparse, far apart, and a
// worst case for recursive splitting.
bricks::AmrField powersOfTwoAlongTheAxes();

// A random layout of `levels` levels whose root size, origin (negative and odd multiples of the
// coarsest width) and refinement probability vary with `seed`.
bricks::AmrField variedRandomLayout(std::uint64_t seed, int levels);

// A level-3 cell [0,8)^3 next to 8^3 level-0 cells filling [8,16) x [0,8) x [0,8).
bricks::AmrField levelJumpOfThree();

// Every cell in exactly one brick; bricks single-level, without holes (each slot's cell sits at
// the slot's position), sides within maxSide; cellIds a permutation.
::testing::AssertionResult bricksAreValid(const bricks::AmrField& field,
                                          const bricks::BrickSet& set, int maxSide);

// Exact check on a voxel grid of half-finest-cell voxels: regions are disjoint, tile the union
// of the domains, list exactly the bricks whose domains cover them and the right finest width;
// the tree's leaves are exactly the regions' boxes and the empty space.
// The region containing p (cell units), located on the region lattice; -1 for none or a point
// that is not finite.
std::int32_t locateCellUnits(const bricks::RegionSet& regions, glm::vec3 p);

::testing::AssertionResult regionsAreValid(const std::vector<shared::Brick>& bricks,
                                           const bricks::RegionSet& regions);

// locate() against a scan over all regions and all brick domains, point by point.
::testing::AssertionResult locateMatchesBruteForce(const std::vector<shared::Brick>& bricks,
                                                   const bricks::RegionSet& regions,
                                                   const std::vector<glm::vec3>& points);

// Points on domain corners and faces, region corners, the root box's faces and corners, random
// quarter-cell points in and around the root box, and random continuous points.
std::vector<glm::vec3> probePoints(const std::vector<shared::Brick>& bricks,
                                   const bricks::RegionSet& regions, std::uint64_t seed, int count);

bool identical(const bricks::BrickSet& a, const bricks::BrickSet& b);
bool identical(const bricks::RegionSet& a, const bricks::RegionSet& b);

}  // namespace amrstream::testing
