#include <algorithm>
#include <climits>
#include <cmath>
#include <random>

#include "flow/cell_point.hpp"
#include "oracles.hpp"

namespace amrstream::testing {

namespace {

using amrstream::CellBox;
using ::testing::AssertionFailure;
using ::testing::AssertionSuccess;

CellBox unionOfDomains(const std::vector<shared::Brick>& bricks) {
  CellBox box{glm::ivec3(INT_MAX), glm::ivec3(INT_MIN)};
  for (const shared::Brick& b : bricks) {
    const CellBox d = bricks::brickDomainDoubled(b);
    box.lower = glm::min(box.lower, d.lower);
    box.upper = glm::max(box.upper, d.upper);
  }
  return box;
}

bool contains(const CellBox& outer, const CellBox& inner) {
  return glm::all(glm::lessThanEqual(outer.lower, inner.lower)) &&
         glm::all(glm::greaterThanEqual(outer.upper, inner.upper));
}

// p2 is a point in doubled coordinates.
bool containsPoint(const CellBox& doubled, const double (&p2)[3]) {
  return p2[0] >= doubled.lower.x && p2[0] < doubled.upper.x && p2[1] >= doubled.lower.y &&
         p2[1] < doubled.upper.y && p2[2] >= doubled.lower.z && p2[2] < doubled.upper.z;
}

glm::vec3 cellUnits(glm::ivec3 lattice) { return 0.5f * glm::vec3(lattice); }

CellBox latticeBox(glm::ivec3 lower, glm::ivec3 upper) { return {lower, upper}; }

// Half-finest-cell voxels over a box in doubled coordinates.
class VoxelGrid {
 public:
  explicit VoxelGrid(CellBox box) : box_(box), dims_(box.upper - box.lower) {}
  std::size_t size() const { return std::size_t(dims_.x) * dims_.y * dims_.z; }
  // Calls f(voxel index) for every voxel of `b` (inside the grid); stops when f returns false.
  template <typename F>
  bool forEach(const CellBox& b, F f) const {
    for (int z = b.lower.z; z < b.upper.z; ++z)
      for (int y = b.lower.y; y < b.upper.y; ++y) {
        const std::size_t row =
            std::size_t(dims_.x) *
            (std::size_t(y - box_.lower.y) + std::size_t(dims_.y) * std::size_t(z - box_.lower.z));
        for (int x = b.lower.x - box_.lower.x; x < b.upper.x - box_.lower.x; ++x)
          if (!f(row + std::size_t(x))) return false;
      }
    return true;
  }

 private:
  CellBox box_;
  glm::ivec3 dims_;
};

float finestWidth(const std::vector<shared::Brick>& bricks, const std::vector<std::uint32_t>& ids) {
  float width = INFINITY;
  for (std::uint32_t id : ids) width = std::min(width, float(1 << bricks[id].level));
  return width;
}

::testing::AssertionResult treeIsValid(const bricks::RegionSet& regions, const CellBox& root,
                                       const VoxelGrid& grid, const std::vector<int>& cover) {
  std::vector<char> nodeSeen(regions.tree.size(), 0), regionSeen(regions.regions.size(), 0);
  std::vector<std::pair<std::uint32_t, CellBox>> stack{{0u, root}};
  while (!stack.empty()) {
    const auto [index, box] = stack.back();
    stack.pop_back();
    if (index >= regions.tree.size() || nodeSeen[index])
      return AssertionFailure() << "tree node " << index << " out of range or reached twice";
    nodeSeen[index] = 1;
    const shared::RegionTreeNode& node = regions.tree[index];
    if (node.axis == AMRSTREAM_TREE_LEAF) {
      if (node.child == AMRSTREAM_NO_REGION) {
        if (!grid.forEach(box, [&](std::size_t v) { return cover[v] == 0; }))
          return AssertionFailure() << "empty leaf " << index << " overlaps a domain";
        continue;
      }
      if (node.child >= regions.regions.size() || regionSeen[node.child])
        return AssertionFailure() << "leaf " << index << " names region " << node.child;
      regionSeen[node.child] = 1;
      const shared::Region& r = regions.regions[node.child];
      const CellBox rb = latticeBox(r.lower, r.upper);
      if (rb.lower != box.lower || rb.upper != box.upper)
        return AssertionFailure() << "region " << node.child << " differs from its leaf's box";
      continue;
    }
    const int a = int(node.axis);
    const int split = node.split;
    if (a > 2 || split <= box.lower[a] || split >= box.upper[a])
      return AssertionFailure() << "node " << index << " has a bad axis or split";
    CellBox lower = box, upper = box;
    lower.upper[a] = split;
    upper.lower[a] = split;
    stack.push_back({node.child, lower});
    stack.push_back({node.child + 1, upper});
  }
  if (std::count(nodeSeen.begin(), nodeSeen.end(), 0) != 0)
    return AssertionFailure() << "the tree has unreachable nodes";
  if (std::count(regionSeen.begin(), regionSeen.end(), 0) != 0)
    return AssertionFailure() << "some regions are in no leaf";
  return AssertionSuccess();
}

// Every node reached once from the root with valid indices, so that locate() terminates.
::testing::AssertionResult treeIsWellFormed(const bricks::RegionSet& regions) {
  if (regions.tree.empty()) return AssertionFailure() << "empty tree";
  std::vector<char> seen(regions.tree.size(), 0);
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const std::uint32_t index = stack.back();
    stack.pop_back();
    if (index >= regions.tree.size() || seen[index])
      return AssertionFailure() << "tree node " << index << " out of range or reached twice";
    seen[index] = 1;
    const shared::RegionTreeNode& node = regions.tree[index];
    if (node.axis == AMRSTREAM_TREE_LEAF) {
      if (node.child != AMRSTREAM_NO_REGION && node.child >= regions.regions.size())
        return AssertionFailure() << "leaf " << index << " names region " << node.child;
    } else if (node.axis > 2) {
      return AssertionFailure() << "tree node " << index << " has axis " << node.axis;
    } else {
      stack.push_back(node.child);
      stack.push_back(node.child + 1);
    }
  }
  return AssertionSuccess();
}

}  // namespace

std::int32_t locateCellUnits(const bricks::RegionSet& regions, glm::vec3 p) {
  const flow::CellPoint point(p);
  return flow::isNear(point) ? regions.locate(flow::latticeOf(point)) : -1;
}

::testing::AssertionResult regionsAreValid(const std::vector<shared::Brick>& bricks,
                                           const bricks::RegionSet& regions) {
  const CellBox root = unionOfDomains(bricks);
  if (latticeBox(regions.lower, regions.upper).lower != root.lower ||
      latticeBox(regions.lower, regions.upper).upper != root.upper)
    return AssertionFailure() << "root box differs from the bounds of the domains";
  const VoxelGrid grid(root);
  std::vector<int> cover(grid.size(), 0), owner(grid.size(), -1);
  for (const shared::Brick& b : bricks)
    grid.forEach(bricks::brickDomainDoubled(b), [&](std::size_t v) { return ++cover[v], true; });

  for (std::size_t r = 0; r < regions.regions.size(); ++r) {
    const shared::Region& region = regions.regions[r];
    const CellBox box = latticeBox(region.lower, region.upper);
    if (!contains(root, box) || glm::any(glm::lessThanEqual(box.upper, box.lower)))
      return AssertionFailure() << "region " << r << " has a bad box";
    if (region.brickCount == 0 ||
        std::size_t(region.brickOffset) + region.brickCount > regions.regionBricks.size())
      return AssertionFailure() << "region " << r << " has a bad brick list";
    const std::vector<std::uint32_t> ids(
        regions.regionBricks.begin() + region.brickOffset,
        regions.regionBricks.begin() + region.brickOffset + region.brickCount);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (ids[i] >= bricks.size() || (i > 0 && ids[i] <= ids[i - 1]))
        return AssertionFailure() << "region " << r << " brick list not sorted or out of range";
      if (!contains(bricks::brickDomainDoubled(bricks[ids[i]]), box))
        return AssertionFailure() << "region " << r << " lists brick " << ids[i]
                                  << " whose domain does not cover it";
    }
    if (region.finestCellWidth != finestWidth(bricks, ids))
      return AssertionFailure() << "region " << r << " has the wrong finest cell width";
    // Listed domains cover every voxel; equal counts mean no other domain does.
    const bool ok = grid.forEach(box, [&](std::size_t v) {
      if (owner[v] != -1 || cover[v] != int(region.brickCount)) return false;
      owner[v] = int(r);
      return true;
    });
    if (!ok)
      return AssertionFailure() << "region " << r
                                << " overlaps another region or is covered by unlisted domains";
  }
  for (std::size_t v = 0; v < grid.size(); ++v)
    if ((owner[v] >= 0) != (cover[v] > 0))
      return AssertionFailure() << "regions do not tile the union of the domains";
  return treeIsValid(regions, root, grid, cover);
}

::testing::AssertionResult locateMatchesBruteForce(const std::vector<shared::Brick>& bricks,
                                                   const bricks::RegionSet& regions,
                                                   const std::vector<glm::vec3>& points) {
  if (::testing::AssertionResult formed = treeIsWellFormed(regions); !formed) return formed;
  std::vector<CellBox> regionBoxes, domains;
  for (const shared::Region& r : regions.regions)
    regionBoxes.push_back(latticeBox(r.lower, r.upper));
  for (const shared::Brick& b : bricks) domains.push_back(bricks::brickDomainDoubled(b));
  for (const glm::vec3 p : points) {
    const double p2[3] = {2.0 * p.x, 2.0 * p.y, 2.0 * p.z};
    std::int32_t expected = -1;
    for (std::size_t r = 0; r < regionBoxes.size(); ++r) {
      if (!containsPoint(regionBoxes[r], p2)) continue;
      if (expected != -1)
        return AssertionFailure() << "point in regions " << expected << " and " << r;
      expected = std::int32_t(r);
    }
    const std::int32_t found = locateCellUnits(regions, p);
    if (found != expected)
      return AssertionFailure() << "locate(" << p.x << "," << p.y << "," << p.z << ") = " << found
                                << ", brute force " << expected;
    std::vector<std::uint32_t> covering;
    for (std::uint32_t b = 0; b < bricks.size(); ++b)
      if (containsPoint(domains[b], p2)) covering.push_back(b);
    if (found < 0) {
      if (!covering.empty())
        return AssertionFailure() << "no region at a point in " << covering.size() << " domains";
      continue;
    }
    const shared::Region& region = regions.regions[found];
    const std::vector<std::uint32_t> listed(
        regions.regionBricks.begin() + region.brickOffset,
        regions.regionBricks.begin() + region.brickOffset + region.brickCount);
    if (listed != covering || region.finestCellWidth != finestWidth(bricks, covering))
      return AssertionFailure() << "region " << found << " at (" << p.x << "," << p.y << "," << p.z
                                << ") does not list the covering bricks";
  }
  return AssertionSuccess();
}

std::vector<glm::vec3> probePoints(const std::vector<shared::Brick>& bricks,
                                   const bricks::RegionSet& regions, std::uint64_t seed,
                                   int count) {
  std::mt19937_64 rng(seed);
  const auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  std::vector<glm::vec3> points;
  for (int corner = 0; corner < 8; ++corner)
    points.push_back(cellUnits(glm::ivec3(corner & 1 ? regions.upper.x : regions.lower.x,
                                          corner & 2 ? regions.upper.y : regions.lower.y,
                                          corner & 4 ? regions.upper.z : regions.lower.z)));
  const glm::vec3 rootLower = cellUnits(regions.lower), rootUpper = cellUnits(regions.upper);
  for (int a = 0; a < 3; ++a) {  // centres of the root box's lower and upper faces
    glm::vec3 p = 0.5f * (rootLower + rootUpper);
    p[a] = rootLower[a];
    points.push_back(p);
    p[a] = rootUpper[a];
    points.push_back(p);
  }
  for (int i = 0; i < count / 4 && !bricks.empty(); ++i) {
    const CellBox d = bricks::brickDomainDoubled(bricks[pick(0, int(bricks.size()) - 1)]);
    glm::ivec3 corner, onFace;
    for (int a = 0; a < 3; ++a) {
      corner[a] = pick(0, 1) ? d.upper[a] : d.lower[a];
      onFace[a] = pick(d.lower[a], d.upper[a]);
    }
    onFace[pick(0, 2)] = corner[pick(0, 2)];  // usually on a face, sometimes an edge
    points.push_back(glm::vec3(corner) * 0.5f);
    points.push_back(glm::vec3(onFace) * 0.5f);
  }
  for (int i = 0; i < count / 8 && !regions.regions.empty(); ++i) {
    const shared::Region& r = regions.regions[pick(0, int(regions.regions.size()) - 1)];
    points.push_back(cellUnits(r.lower));
    points.push_back(cellUnits(r.upper));
  }
  const glm::ivec3 lo4 = 2 * regions.lower, hi4 = 2 * regions.upper;
  for (int i = 0; i < count / 2; ++i)  // quarter-cell points in and around the root box
    points.push_back(0.25f * glm::vec3(pick(lo4.x - 4, hi4.x + 4), pick(lo4.y - 4, hi4.y + 4),
                                       pick(lo4.z - 4, hi4.z + 4)));
  std::uniform_real_distribution<float> unit(-0.1f, 1.1f);
  for (int i = 0; i < count / 8; ++i)
    points.push_back(rootLower +
                     (rootUpper - rootLower) * glm::vec3(unit(rng), unit(rng), unit(rng)));
  return points;
}

}  // namespace amrstream::testing
