#pragma once
// Ways to place seeds besides a file and a random box (seeds.hpp): a rake along a line, a regular
// grid in a box (a box of zero thickness is a plane), and the paper's strategy, random seeds
// among the cells with the highest values of a scalar. All in physical coordinates.

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "bricks/amr_field.hpp"
#include "seeds.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

// `count` points evenly spaced from `from` to `to`, both included (one point: the midpoint).
SeedList seedsAlongLine(glm::dvec3 from, glm::dvec3 to, std::size_t count);

// Cell-centred regular grid of counts.x * counts.y * counts.z points in [lower, upper]; an axis
// with count 1 gets the box's middle, so a zero-thickness box with one count is a plane.
SeedList seedsOnGrid(glm::dvec3 lower, glm::dvec3 upper, glm::ivec3 counts);

// True when `cellUnits` (finest-cell units) lies inside one of the volume's cells, not in a hole
// of the domain nor only in the half-cell padding of a brick's domain.
bool insideACell(const VectorVolume& volume, glm::dvec3 cellUnits);

// `count` seeds uniform in the physical box [lower, upper) restricted to the cells: points that
// fall in holes are drawn again. With no holes in the box this equals randomSeedsInBox. Throws
// InputError when under 1 in 1000 draws lands in a cell (a box that is nearly all holes).
SeedList randomSeedsInCells(const VectorVolume& volume, glm::dvec3 lower, glm::dvec3 upper,
                            std::size_t count, std::uint64_t seed);

// Cells whose values are shared out among processes (MPI ranks over data, each holding the
// values of its part): each process counts the cells it owns, and the two functions combine
// what the processes found, so that every process chooses the seeds one process would.
struct SharedCells {
  std::span<const std::uint8_t> owned;  // per cell: 1 where this process counts it
  // Element-wise sums over the processes, in place.
  std::function<void(std::vector<std::uint64_t>&)> sumCounts;
  // Every process's cells (indices) with their values, each process giving its own in increasing
  // order: all of them, in increasing order.
  std::function<std::vector<std::pair<std::uint32_t, float>>(
      std::vector<std::pair<std::uint32_t, float>>)>
      gatherCells;
};

struct DensestCellsOptions {
  std::string channel;       // the scalar, e.g. "dens"
  double percentile = 90.0;  // candidate cells have values at or above this percentile
  bool weighted = false;     // pick candidates with probability proportional to the value
  std::size_t count = 256;
  std::uint64_t seed = 1;
  const SharedCells* shared = nullptr;  // this process holds some of the values only
};

// Seeds uniformly inside randomly chosen candidate cells (with repetition). Throws InputError
// for an unknown channel, a percentile outside [0, 100], or weights that are not positive.
SeedList seedsInDensestCells(const bricks::AmrField& field, const DensestCellsOptions& options);

// The value of rank `rank` (0-based, < values.size()) among finite `values` in increasing order:
// what std::nth_element would place there, up to the sign of a zero (which compares equal).
// Two parallel histogram passes over the values' bits. With `shared`, among every process's
// owned values.
float valueAtRank(std::span<const float> values, std::size_t rank,
                  const SharedCells* shared = nullptr);

}  // namespace amrstream::flow
