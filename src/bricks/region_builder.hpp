#pragma once
// Active brick regions (ABRs; docs/architecture.md, "Active brick regions"): disjoint half-open
// boxes that tile the union of the brick domains, each listing the bricks whose domain covers it
// and its finest cell width, plus the kd-tree that produced them, used for point location.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "../../shaders/glsl/shared/amr_types.h"

namespace amrstream::bricks {

struct RegionSet {
  std::vector<shared::Region> regions;
  std::vector<std::uint32_t> regionBricks;   // brick ids; see Region::brickOffset
  std::vector<shared::RegionTreeNode> tree;  // tree[0] is the root; its box is [lower, upper)
  glm::vec3 lower{0.0f};                     // bounds of the union of all brick domains
  glm::vec3 upper{0.0f};

  // Id of the region whose half-open box contains p (finest-cell units), or -1 when p is in no
  // region (outside the root box or in empty space between domains).
  std::int32_t locate(glm::vec3 p) const;
};

// Parallel; O(N log N) in the number of bricks for the layouts AMR codes produce.
RegionSet buildRegions(const std::vector<shared::Brick>& bricks);

}  // namespace amrstream::bricks
