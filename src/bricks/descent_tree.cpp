#include "descent_tree.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>

namespace amrstream::bricks {

namespace {

using Extent = glm::u64vec3;

Extent cellsAt(const Extent& extent, std::uint32_t shift) {
  const std::uint64_t width = std::uint64_t(1) << shift;
  return (extent + Extent(width - 1)) / Extent(width);
}

std::uint64_t product(const Extent& e) { return e.x * e.y * e.z; }

// Whether e.x * e.y * e.z <= limit, without overflowing (an axis may have 2^32 cells).
bool atMost(const Extent& e, std::uint64_t limit) {
  return e.x <= limit && e.y <= limit / e.x && e.z <= limit / (e.x * e.y);
}

// The deepest node all of the cell [lower, lower + width)^3 reaches from the root.
std::uint32_t startNode(const std::vector<shared::RegionTreeNode>& tree, const glm::i64vec3& lower,
                        std::int64_t width) {
  std::uint32_t index = 0;
  while (tree[index].axis != AMRSTREAM_TREE_LEAF) {
    const shared::RegionTreeNode& node = tree[index];
    const int axis = int(node.axis);
    if (lower[axis] + width <= node.split)
      index = node.child;
    else if (lower[axis] >= node.split)
      index = node.child + 1;
    else
      break;
  }
  return index;
}

}  // namespace

DescentTree buildDescentTree(const RegionSet& regions, std::uint32_t maxCells) {
  DescentTree out;
  shared::RegionTreeGrid& grid = out.grid;
  const std::vector<shared::RegionTreeNode>& tree = regions.tree;
  Extent extent;
  for (int a = 0; a < 3; ++a)
    extent[a] = regions.upper[a] > regions.lower[a]
                    ? std::uint64_t(std::int64_t(regions.upper[a]) - regions.lower[a])
                    : 1;
  const std::uint64_t limit =
      std::max<std::uint64_t>(1, std::min<std::uint64_t>(maxCells, 2 * tree.size()));
  std::uint32_t shift = 0;
  while (shift < 31 && !atMost(cellsAt(extent, shift), limit)) ++shift;
  const Extent cells = cellsAt(extent, shift);
  grid.lower = regions.lower;
  grid.last = glm::ivec3(glm::i64vec3(regions.lower) + glm::i64vec3(extent) - glm::i64vec3(1));
  grid.shift = shift;
  grid.cells = glm::uvec3(cells);
  grid.entryCount = static_cast<std::uint32_t>(product(cells));

  const std::uint32_t starts = grid.entryCount;
  out.nodes.resize(starts + tree.size());
  for (std::size_t i = 0; i < tree.size(); ++i) {
    shared::RegionTreeNode node = tree[i];
    if (node.axis != AMRSTREAM_TREE_LEAF) node.child += starts;
    out.nodes[starts + i] = node;
  }
  if (tree.empty()) {  // no tree: every cell is empty space
    std::fill_n(out.nodes.begin(), starts,
                shared::RegionTreeNode{0, AMRSTREAM_TREE_LEAF, AMRSTREAM_NO_REGION});
    return out;
  }
  const std::int64_t width = std::int64_t(1) << shift;
  tbb::parallel_for(std::uint32_t(0), grid.cells.z, [&](std::uint32_t z) {
    for (std::uint32_t y = 0; y < grid.cells.y; ++y)
      for (std::uint32_t x = 0; x < grid.cells.x; ++x) {
        const glm::i64vec3 lower = glm::i64vec3(regions.lower) + glm::i64vec3(x, y, z) * width;
        out.nodes[x + grid.cells.x * (y + std::size_t(grid.cells.y) * z)] =
            out.nodes[starts + startNode(tree, lower, width)];
      }
  });
  return out;
}

std::vector<std::byte> DescentTree::bytes() const {
  std::vector<std::byte> out(sizeof(grid) + nodes.size() * sizeof(shared::RegionTreeNode));
  std::memcpy(out.data(), &grid, sizeof(grid));
  if (!nodes.empty())
    std::memcpy(out.data() + sizeof(grid), nodes.data(), nodes.size() * sizeof(nodes[0]));
  return out;
}

std::int32_t DescentTree::locate(glm::ivec3 k) const {
  // Unsigned: k - lower spans up to 2^32 on a lattice that fills 32 bits.
  const glm::uvec3 cell =
      (glm::uvec3(glm::clamp(k, grid.lower, grid.last)) - glm::uvec3(grid.lower)) >> grid.shift;
  shared::RegionTreeNode node = nodes[cell.x + grid.cells.x * (cell.y + grid.cells.y * cell.z)];
  while (node.axis != AMRSTREAM_TREE_LEAF)
    node = nodes[k[int(node.axis)] < node.split ? node.child : node.child + 1];
  return node.child == AMRSTREAM_NO_REGION ? -1 : std::int32_t(node.child);
}

}  // namespace amrstream::bricks
