#pragma once
// Space cut among the ranks for --distribute data: one box per rank (finest-cell units of the
// volume, half-open), the boxes tiling the domain, found by recursive bisection. Each cut, on
// whichever axis, makes the larger side's cells per rank smallest, counting with each side the
// cells within the halo of the cut that its ranks will hold too; so cuts avoid dense regions.

#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::mpi {

struct DataPartition {
  std::vector<glm::ivec3> lower, upper;  // per rank

  int parts() const { return int(lower.size()); }
  // The rank whose box holds `cellPoint` (finest-cell units); outside every box (beyond the
  // domain), the box nearest to it.
  int ownerOf(glm::dvec3 cellPoint) const;
};

// Deterministic: every rank computes the same partition from the same cells. `halo`: finest
// cells each rank holds beyond its box (0: cut through the median cell of the longest axis).
// With `seeds` (the field's cell units) and a halo, a side's load is the larger of its shares of
// the cells and of the seeds, each per part: where seeds crowd, the cuts trade balanced memory
// for balanced lines, as far as the cells' balance gets no worse than the seeds'.
DataPartition partitionCells(const bricks::AmrField& field, int parts, double halo,
                             std::span<const glm::dvec3> seeds = {});

}  // namespace amrstream::mpi
