#pragma once
// Private to the region builder: the kd-tree of active brick regions is built in chunks, one per
// task, and the chunks are concatenated in a fixed order afterwards, so the output does not
// depend on thread scheduling.

#include <tbb/task_group.h>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "../../shaders/glsl/shared/amr_types.h"
#include "amr_field.hpp"

namespace amrstream::bricks::detail {

// Marks a node whose subtree is the chunk children[node.child]; that chunk's root replaces it.
inline constexpr std::uint32_t kChunkStubAxis = 4;

// Brick domains in doubled coordinates (brickDomainDoubled) and finest-cell widths of bricks.
struct RegionInputs {
  std::vector<CellBox> domains;
  std::vector<float> cellWidths;
};

// A subtree. Node, region and brick-list indices are local: node 0 is the chunk's root, a leaf's
// child indexes `regions`, a region's brickOffset indexes `regionBricks`.
struct RegionChunk {
  std::vector<shared::RegionTreeNode> nodes;
  std::vector<shared::Region> regions;
  std::vector<std::uint32_t> regionBricks;
  std::vector<std::unique_ptr<RegionChunk>> children;
  std::uint32_t stubInParent = 0;  // the parent's node that this chunk's root replaces
};

// Builds the subtree of `box` (doubled coordinates) over the bricks whose domains overlap it with
// positive volume, listed in ascending order. Subtrees with many bricks go to child chunks,
// built by tasks run in `tasks`; the caller waits for `tasks` before reading any chunk.
void buildRegionChunk(RegionChunk& chunk, const RegionInputs& inputs, CellBox box,
                      std::span<const std::uint32_t> brickIds, tbb::task_group& tasks);

}  // namespace amrstream::bricks::detail
