#include "data_partition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace amrstream::dist {

namespace {

// Cells' centres, doubled so that they are integers: 2 * lower + width.
using Centres = std::vector<glm::i64vec3>;

void bisect(Centres::iterator first, Centres::iterator last, glm::ivec3 lower, glm::ivec3 upper,
            int firstPart, int parts, DataPartition& partition) {
  if (parts == 1) {
    partition.lower[std::size_t(firstPart)] = lower;
    partition.upper[std::size_t(firstPart)] = upper;
    return;
  }
  const glm::ivec3 extent = upper - lower;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const int leftParts = parts / 2;
  const std::ptrdiff_t cells = last - first;
  const auto middle = first + cells * leftParts / parts;
  int split = lower[axis] + int(std::int64_t(extent[axis]) * leftParts / parts);
  if (cells > 0 && middle != last && extent[axis] >= 2) {
    std::nth_element(first, middle, last, [axis](const glm::i64vec3& a, const glm::i64vec3& b) {
      return a[axis] < b[axis];
    });
    // The plane through the median centre, rounded down to a finest cell, kept inside the box
    // so that neither side is empty.
    const std::int64_t plane = (*middle)[axis] / 2;
    split = int(std::clamp<std::int64_t>(plane, lower[axis] + 1, upper[axis] - 1));
  }
  const auto below = std::partition(first, last, [axis, split](const glm::i64vec3& c) {
    return c[axis] < 2 * std::int64_t(split);
  });
  glm::ivec3 leftUpper = upper, rightLower = lower;
  leftUpper[axis] = split;
  rightLower[axis] = split;
  bisect(first, below, lower, leftUpper, firstPart, leftParts, partition);
  bisect(below, last, rightLower, upper, firstPart + leftParts, parts - leftParts, partition);
}

}  // namespace

int DataPartition::ownerOf(glm::dvec3 p) const {
  int best = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (int k = 0; k < parts(); ++k) {
    const glm::dvec3 lo(lower[std::size_t(k)]), hi(upper[std::size_t(k)]);
    if (glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThan(p, hi))) return k;
    const glm::dvec3 outside = glm::max(lo - p, glm::max(p - hi, glm::dvec3(0.0)));
    if (const double d = glm::length(outside); d < nearest) {
      nearest = d;
      best = k;
    }
  }
  return best;
}

DataPartition partitionCells(const bricks::AmrField& field, int parts) {
  Centres centres(field.cellCount());
  for (std::size_t i = 0; i < centres.size(); ++i)
    centres[i] = std::int64_t(2) * glm::i64vec3(field.lowers()[i]) +
                 (std::int64_t(1) << field.levels()[i]);
  DataPartition partition;
  partition.lower.resize(std::size_t(std::max(parts, 1)));
  partition.upper.resize(partition.lower.size());
  const bricks::CellBox bounds = field.bounds();
  bisect(centres.begin(), centres.end(), bounds.lower, bounds.upper, 0, partition.parts(),
         partition);
  return partition;
}

}  // namespace amrstream::dist
