#pragma once
// The region tree as the GPU kernels descend it (include/locate_tree.glsl). Point location is a
// chain of dependent loads, one per tree level, and a GPU waits out each one: a descent from the
// root of a 70 M-cell cloud's tree costs as much as two or three samples. A grid over the root
// box gives every cell the deepest node that all of the cell's points reach, so a descent starts
// there and skips the levels above the cell's scale; it ends in the same leaf as one from the root.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "../../shaders/glsl/shared/amr_types.h"
#include "region_builder.hpp"

namespace amrstream::bricks {

// The most grid cells: 2^22 start nodes of 12 bytes (48 MiB). A tree gets at most twice as many
// cells as it has nodes: 2.2 M cells (25 MiB) for the 1.2 M nodes of a cloud of 72.8 M cells,
// whose descents then start 32 finest cells from the leaves' scale (docs/benchmarks.md).
inline constexpr std::uint32_t kMaxDescentCells = 1u << 22;

struct DescentTree {
  shared::RegionTreeGrid grid{};
  // The grid's start nodes, then the tree with its child indices moved past them.
  std::vector<shared::RegionTreeNode> nodes;

  // The GPU buffer: the grid, then the nodes.
  std::vector<std::byte> bytes() const;
  // Twin of locateInRegions() in locate_tree.glsl: the leaf a descent from the root reaches, for
  // any k (no root box test): a region id, or -1 for empty space.
  std::int32_t locate(glm::ivec3 k) const;
};

// The finest grid of at most min(maxCells, 2 x tree nodes) cells (at least one), with
// power-of-two cells no wider than 2^31 lattice units: a root box wider than that on some axis
// gets two cells along it, whatever the limit.
DescentTree buildDescentTree(const RegionSet& regions, std::uint32_t maxCells = kMaxDescentCells);

}  // namespace amrstream::bricks
