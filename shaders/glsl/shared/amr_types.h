// Buffer structs shared by the C++ host code and the GLSL kernels (scalar block layout).
// Coordinates are in finest-cell units, centred on the domain (docs/architecture.md, "Positions");
// level 0 is the finest level, a level-L cell is 2^L wide. Region boxes and tree splits are on the
// region lattice: doubled finest-cell units, where every face of a brick's domain (padded by half
// a cell) lies on an integer, so containment is exact integer arithmetic at any depth.
#ifndef AMRSTREAM_SHARED_AMR_TYPES_H
#define AMRSTREAM_SHARED_AMR_TYPES_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

// A box of same-level cells with no holes. The value of cell (ix, iy, iz) of the brick is at
// slot valueOffset + ix + size.x * (iy + size.y * iz) of the brick-ordered value arrays.
struct Brick {
  ivec3 lower;       // lower corner of the brick
  int level;         // level of all its cells
  ivec3 size;        // cells per axis
  uint valueOffset;  // first slot of the brick in the value arrays
};

// An active brick region: a box in which every point lies in the domains of the same bricks.
// The box is half-open, [lower, upper), on the region lattice.
struct Region {
  ivec3 lower;
  // The region's bricks are regionBricks[brickOffset .. brickOffset + brickCount).
  uint brickOffset;
  ivec3 upper;
  uint brickCount;
  float finestCellWidth;  // width of the finest cell among the region's bricks
};

// Node of the kd-tree whose leaves are the regions (and the empty space between them).
// Interior node: a point whose lattice coordinate k has k[axis] < split goes to child, else to
// child + 1. Leaf: axis == AMRSTREAM_TREE_LEAF and child is a region id or AMRSTREAM_NO_REGION.
struct RegionTreeNode {
  int split;
  uint axis;
  uint child;
};

// A sample whose tent weights sum to no more than this is invalid (no brick covers it).
#define AMRSTREAM_MIN_WEIGHT_SUM 1e-20f

// The head of the region tree as the GPU kernels read it (src/bricks/descent_tree.hpp): a grid
// of cells 2^shift lattice units wide from lower, each holding a copy of the deepest tree node
// that every point of the cell reaches, so that point location starts its descent there rather
// than at the root. The buffer holds this head, then the grid's entryCount start nodes (x
// fastest), then the tree, its child indices moved past the start nodes.
struct RegionTreeGrid {
  ivec3 lower;      // the root box's lower corner
  uint shift;       // cells are 2^shift lattice units wide
  ivec3 last;       // points are clamped to [lower, last] to pick their cell
  uint entryCount;  // cells.x * cells.y * cells.z
  uvec3 cells;
  uint unused;
};

#define AMRSTREAM_TREE_LEAF 3u
#define AMRSTREAM_NO_REGION 0xffffffffu

#ifdef __cplusplus
static_assert(sizeof(Brick) == 32 && offsetof(Brick, size) == 16 &&
              offsetof(Brick, valueOffset) == 28);
static_assert(sizeof(RegionTreeGrid) == 48 && offsetof(RegionTreeGrid, cells) == 32);
static_assert(sizeof(Region) == 36 && offsetof(Region, upper) == 16 &&
              offsetof(Region, finestCellWidth) == 32);
static_assert(sizeof(RegionTreeNode) == 12);
}  // namespace amrstream::shared
#endif

#endif
