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

#include "../bricks/amr_field.hpp"

namespace amrstream::synth {

inline constexpr int kMaxNestLevels = 30;

struct NestOptions {
  int levels = 5;      // 1 to kMaxNestLevels
  int rootCells = 6;   // coarsest cells per axis; at least blockCells / 2 + 2 when levels > 1
                       // (2 for an octree)
  int blockCells = 8;  // cells per axis of each finer level's cube: even, at least 2
  // The nest's centre and the spiral's, as a fraction of the unit domain: off the domain's
  // middle, so the finest cells lie far from the coordinate origin and on no coarser cell face.
  // A cube must nest with its margin: with the default sizes each coordinate lies in about
  // [0.42, 0.58]; more root cells widen the range.
  glm::dvec3 centre{0.45, 0.55, 0.47};
  double rotationRate = 2.0 * std::numbers::pi;    // one turn per unit time
  double expansionRate = 0.5 * std::numbers::ln2;  // the offset from the centre doubles in 2 turns
  // Unit-domain lengths per unit time; the spiral's velocity is scaled down to it where faster.
  double maxSpeed = std::numeric_limits<double>::infinity();
  double time = 0.0;  // the snapshot's time in the DatasetInfo (the field is steady)
};

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
