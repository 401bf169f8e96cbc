#pragma once
// Space cut among the ranks for --distribute data: one box per rank (finest-cell units of the
// volume, half-open), the boxes tiling the domain, found by recursive bisection that balances
// the leaf cells whose centres lie in each box.

#include <glm/glm.hpp>
#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::dist {

struct DataPartition {
  std::vector<glm::ivec3> lower, upper;  // per rank

  int parts() const { return int(lower.size()); }
  // The rank whose box holds `cellPoint` (finest-cell units); outside every box (beyond the
  // domain), the box nearest to it.
  int ownerOf(glm::dvec3 cellPoint) const;
};

// Deterministic: every rank computes the same partition from the same cells.
DataPartition partitionCells(const bricks::AmrField& field, int parts);

}  // namespace amrstream::dist
