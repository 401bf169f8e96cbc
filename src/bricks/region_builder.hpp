#pragma once
// Active brick regions (ABRs; docs/architecture.md, "Active brick regions"): disjoint half-open
// boxes that tile the union of the brick domains, each listing the bricks whose domain covers it
// and its finest cell width, plus the kd-tree that produced them, used for point location.

#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "../../shaders/glsl/shared/amr_types.h"
#include "amr_field.hpp"

namespace amrstream::bricks {

struct RegionSet {
  std::vector<shared::Region> regions;
  std::vector<std::uint32_t> regionBricks;   // brick ids; see Region::brickOffset
  std::vector<shared::RegionTreeNode> tree;  // tree[0] is the root; its box is [lower, upper)
  glm::ivec3 lower{0};                       // lattice bounds of the union of the brick domains
  glm::ivec3 upper{0};

  // Id of the region whose half-open box contains the lattice point k, or -1 when k is in no
  // region (outside the root box or in empty space between domains).
  std::int32_t locate(glm::ivec3 k) const;
};

// Parallel; O(N log N) in the number of bricks for the layouts AMR codes produce. With `domain`
// (finest-cell units), the brick domains are clipped to it, grown by the widest cell: regions
// beyond serve no point (samplers test the domain first), and periodic images reaching far past
// it keep the lattice within 32 bits. Throws std::invalid_argument when the lattice bounds do not
// fit 32 bits.
RegionSet buildRegions(const std::vector<shared::Brick>& bricks,
                       std::optional<CellBox> domain = std::nullopt);

}  // namespace amrstream::bricks
