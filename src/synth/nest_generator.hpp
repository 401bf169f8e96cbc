#pragma once
// A deep nest of refinement about one point: level levels-1 covers the unit cube with
// rootCells^3 cells, and every finer level k covers a cube of blockCells^3 level-k cells centred
// on the nest's centre, snapped to the next coarser level's cells and inside that level's cube
// with at least one of its cells of margin (proper nesting). The leaf cells of a level are its
// cube minus the next finer cube. Channels velx, vely, velz hold the spiral of spiral_field.hpp
// about the centre, evaluated in double at the cell centres, so streamlines near the centre
// circle it and spiral outward across the levels; with maxSpeed, the spiral's speed is capped
// (scaled down where faster), so coarse cells far from the centre carry no more than it.
//
// Integer arithmetic is 64-bit and the field is evaluated from offsets in finest-cell units, so
// nothing here limits the depth beyond the AmrField's own limits (bricks::kMaxLevel,
// bricks::kMaxExtentBits), which the domain's rootCells * 2^(levels-1) finest cells per axis
// must respect.

#include <glm/glm.hpp>
#include <limits>
#include <numbers>

#include "amrstream/builtin.hpp"
#include "bricks/amr_field.hpp"

namespace amrstream::synth {

// Source "builtin:nest", DatasetInfo as every generator's (builtin_info.hpp). Throws InputError
// naming the option: levels outside 1..kMaxNestLevels, blockCells odd or below 2, rootCells too
// few for the first finer cube or too many for the cell-unit range or for 32-bit cell numbers, a
// centre outside the domain, rates that are not finite, a maxSpeed that is not positive, or a
// cube that does not nest with its margin.
bricks::AmrField generateNest(const NestOptions& options);

// The cells generateNest() makes: the finest cube whole, every other cube less the next finer
// one (in double: a single level of 2^31 root cells per axis has 2^93).
double nestCellCount(const NestOptions& options);

}  // namespace amrstream::synth
