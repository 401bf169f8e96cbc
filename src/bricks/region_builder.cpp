#include "region_builder.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <climits>
#include <numeric>
#include <stdexcept>

#include "brick_builder.hpp"
#include "region_chunk.hpp"

namespace amrstream::bricks {

namespace {

using detail::RegionChunk;

// The domain of a brick on the region lattice, in 64 bits: periodic images may lie a period away.
struct DomainBox64 {
  glm::i64vec3 lower, upper;
};

DomainBox64 doubledDomain64(const shared::Brick& b) {
  const std::int64_t width = std::int64_t(1) << b.level;
  const glm::i64vec3 lower(b.lower);
  return {std::int64_t(2) * lower - width,
          std::int64_t(2) * (lower + glm::i64vec3(b.size) * width) + width};
}

// Where a chunk's output goes in the concatenated arrays. Its root fills the parent's stub node;
// its other nodes, local 1..n-1, go to nodeBase..nodeBase+n-2.
struct Placement {
  const RegionChunk* chunk;
  std::uint32_t rootSlot;
  std::uint32_t nodeBase;
  std::uint32_t regionBase;
  std::uint32_t brickBase;

  std::uint32_t node(std::uint32_t local) const {
    return local == 0 ? rootSlot : nodeBase + local - 1;
  }
};

// Chunks in preorder (the parent before its children, children in creation order), which fixes
// the output order independently of which task built what.
std::vector<Placement> placeChunks(const RegionChunk& root) {
  std::vector<Placement> order;
  std::vector<std::pair<const RegionChunk*, std::size_t>> stack{{&root, 0}};
  std::uint64_t nodes = 1, regions = 0, bricks = 0;
  while (!stack.empty()) {
    const auto [chunk, parent] = stack.back();
    stack.pop_back();
    const std::uint32_t rootSlot = order.empty() ? 0 : order[parent].node(chunk->stubInParent);
    order.push_back(
        {chunk, rootSlot, std::uint32_t(nodes), std::uint32_t(regions), std::uint32_t(bricks)});
    nodes += chunk->nodes.size() - 1;
    regions += chunk->regions.size();
    bricks += chunk->regionBricks.size();
    // Region ids must also fit locate()'s int32 result.
    if (std::max(nodes, bricks) > std::uint64_t(UINT32_MAX) || regions > std::uint64_t(INT32_MAX))
      throw std::length_error("buildRegions: too many tree nodes, regions or brick entries");
    for (auto it = chunk->children.rbegin(); it != chunk->children.rend(); ++it)
      stack.push_back({it->get(), order.size() - 1});
  }
  return order;
}

void concatenate(const RegionChunk& root, RegionSet& out) {
  const std::vector<Placement> order = placeChunks(root);
  const Placement& last = order.back();
  out.tree.resize(last.nodeBase + last.chunk->nodes.size() - 1);
  out.regions.resize(last.regionBase + last.chunk->regions.size());
  out.regionBricks.resize(last.brickBase + last.chunk->regionBricks.size());
  tbb::parallel_for(std::size_t(0), order.size(), [&](std::size_t i) {
    const Placement& p = order[i];
    const RegionChunk& chunk = *p.chunk;
    for (std::uint32_t local = 0; local < chunk.nodes.size(); ++local) {
      shared::RegionTreeNode node = chunk.nodes[local];
      if (node.axis == detail::kChunkStubAxis) continue;  // the child chunk fills it
      if (node.axis != AMRSTREAM_TREE_LEAF)
        node.child = p.node(node.child);
      else if (node.child != AMRSTREAM_NO_REGION)
        node.child += p.regionBase;
      out.tree[p.node(local)] = node;
    }
    for (std::size_t r = 0; r < chunk.regions.size(); ++r) {
      out.regions[p.regionBase + r] = chunk.regions[r];
      out.regions[p.regionBase + r].brickOffset += p.brickBase;
    }
    std::copy(chunk.regionBricks.begin(), chunk.regionBricks.end(),
              out.regionBricks.begin() + p.brickBase);
  });
}

}  // namespace

RegionSet buildRegions(const std::vector<shared::Brick>& bricks, std::optional<CellBox> domain) {
  RegionSet out;
  if (bricks.empty()) {
    out.tree.push_back({0, AMRSTREAM_TREE_LEAF, AMRSTREAM_NO_REGION});
    return out;
  }
  if (bricks.size() > std::size_t(UINT32_MAX))
    throw std::length_error("buildRegions: more than 2^32 - 1 bricks");

  // Bounds of the domains in 64 bits first, so that far-off bricks cannot overflow.
  DomainBox64 clip{glm::i64vec3(INT64_MIN), glm::i64vec3(INT64_MAX)};
  if (domain) {
    int widest = 0;
    for (const shared::Brick& b : bricks) widest = std::max(widest, b.level);
    const std::int64_t width = std::int64_t(1) << widest;
    clip = {std::int64_t(2) * glm::i64vec3(domain->lower) - width,
            std::int64_t(2) * glm::i64vec3(domain->upper) + width};
  }
  std::vector<DomainBox64> domains(bricks.size());
  glm::i64vec3 lower(INT64_MAX), upper(INT64_MIN);
  for (std::size_t i = 0; i < bricks.size(); ++i) {
    const DomainBox64 d = doubledDomain64(bricks[i]);
    domains[i] = {glm::max(d.lower, clip.lower), glm::min(d.upper, clip.upper)};
    if (!glm::all(glm::lessThan(domains[i].lower, domains[i].upper))) continue;
    lower = glm::min(lower, domains[i].lower);
    upper = glm::max(upper, domains[i].upper);
  }
  if (glm::any(glm::greaterThan(lower, upper))) lower = upper = glm::i64vec3(0);
  if (glm::any(glm::lessThan(lower, glm::i64vec3(INT32_MIN))) ||
      glm::any(glm::greaterThan(upper, glm::i64vec3(INT32_MAX))))
    throw std::invalid_argument(
        "buildRegions: brick domains must lie within +-2^30 finest cells of the origin so that "
        "region lattice coordinates fit 32 bits");
  const CellBox root{glm::ivec3(lower), glm::ivec3(upper)};

  detail::RegionInputs inputs{std::vector<CellBox>(bricks.size()),
                              std::vector<float>(bricks.size())};
  tbb::parallel_for(std::size_t(0), bricks.size(), [&](std::size_t i) {
    inputs.domains[i] = {glm::ivec3(glm::min(domains[i].lower, domains[i].upper)),
                         glm::ivec3(domains[i].upper)};
    inputs.cellWidths[i] = float(AmrField::cellWidth(bricks[i].level));
  });

  std::vector<std::uint32_t> ids;  // the bricks whose clipped domain is not empty
  ids.reserve(bricks.size());
  for (std::uint32_t i = 0; i < bricks.size(); ++i)
    if (glm::all(glm::lessThan(domains[i].lower, domains[i].upper))) ids.push_back(i);
  RegionChunk chunk;
  tbb::task_group tasks;
  try {
    detail::buildRegionChunk(chunk, inputs, root, ids, tasks);
  } catch (...) {
    tasks.cancel();
    tasks.wait();
    throw;
  }
  tasks.wait();  // rethrows what a task threw
  concatenate(chunk, out);
  out.lower = root.lower;
  out.upper = root.upper;
  return out;
}

std::int32_t RegionSet::locate(glm::ivec3 k) const {
  if (!glm::all(glm::greaterThanEqual(k, lower)) || !glm::all(glm::lessThan(k, upper))) return -1;
  std::uint32_t index = 0;
  while (tree[index].axis != AMRSTREAM_TREE_LEAF) {
    const shared::RegionTreeNode& node = tree[index];
    index = node.child + (k[int(node.axis)] < node.split ? 0u : 1u);
  }
  const std::uint32_t region = tree[index].child;
  return region == AMRSTREAM_NO_REGION ? -1 : std::int32_t(region);
}

}  // namespace amrstream::bricks
