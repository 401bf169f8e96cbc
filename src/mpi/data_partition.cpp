#include "data_partition.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace amrstream::mpi {

namespace {

// Cells' centres, doubled so that they are integers: 2 * lower + width.
using Centres = std::vector<glm::i64vec3>;

// Histograms of finest-cell planes are used up to this extent; wider boxes are cut at the median.
constexpr int kMaxPlanes = 1 << 22;

struct Cut {
  int axis = 0;
  int plane = 0;
};

// The cut through the median centre along the longest axis, rounded down to a finest cell and
// kept inside the box so that neither side is empty.
Cut medianCut(Centres::iterator first, Centres::iterator last, glm::ivec3 lower, glm::ivec3 upper,
              int leftParts, int parts) {
  const glm::ivec3 extent = upper - lower;
  Cut cut;
  cut.axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  cut.plane = lower[cut.axis] + int(std::int64_t(extent[cut.axis]) * leftParts / parts);
  const std::ptrdiff_t cells = last - first;
  const auto middle = first + cells * leftParts / parts;
  if (cells > 0 && middle != last && extent[cut.axis] >= 2) {
    const int axis = cut.axis;
    std::nth_element(first, middle, last, [axis](const glm::i64vec3& a, const glm::i64vec3& b) {
      return a[axis] < b[axis];
    });
    cut.plane =
        int(std::clamp<std::int64_t>((*middle)[axis] / 2, lower[axis] + 1, upper[axis] - 1));
  }
  return cut;
}

// The centres in each plane along `axis` (planes from `lower`, clamped to the box), at index
// plane + 1; in parallel pieces when there are many centres and few planes.
std::vector<std::int64_t> planeCounts(Centres::iterator first, Centres::iterator last, int axis,
                                      int lower, int planes) {
  using Counts = std::vector<std::int64_t>;
  const auto count = [&](Centres::iterator from, Centres::iterator to, Counts& counts) {
    for (auto c = from; c != to; ++c) {
      const std::int64_t at = std::clamp<std::int64_t>((*c)[axis] / 2 - lower, 0, planes - 1);
      ++counts[std::size_t(at) + 1];
    }
  };
  const std::size_t cells = std::size_t(last - first);
  constexpr std::size_t kPiece = std::size_t(1) << 18;
  if (cells < 4 * kPiece || planes > (1 << 16)) {
    Counts counts(std::size_t(planes) + 1, 0);
    count(first, last, counts);
    return counts;
  }
  tbb::enumerable_thread_specific<Counts> perThread(Counts(std::size_t(planes) + 1, 0));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells, kPiece),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      count(first + std::ptrdiff_t(range.begin()),
                            first + std::ptrdiff_t(range.end()), perThread.local());
                    });
  Counts counts(std::size_t(planes) + 1, 0);
  for (const Counts& piece : perThread)
    for (std::size_t i = 0; i < counts.size(); ++i) counts[i] += piece[i];
  return counts;
}

// The cells of a box, and the seeds in it.
struct InBox {
  Centres::iterator first, last, firstSeed, lastSeed;
};

// The cut, on any axis, that makes the larger of the two sides' loads smallest. A side's load is
// its share of the cells per part, counting the cells within `halo` finest cells of the cut that
// it will hold as well (a cut through sparse cells costs less halo than one through a dense
// filament), or its share of the seeds per part when that is larger.
Cut haloAwareCut(const InBox& in, glm::ivec3 lower, glm::ivec3 upper, int leftParts, int parts,
                 double halo) {
  const glm::ivec3 extent = upper - lower;
  if (halo <= 0.0 || glm::any(glm::greaterThan(extent, glm::ivec3(kMaxPlanes))))
    return medianCut(in.first, in.last, lower, upper, leftParts, parts);
  const std::int64_t reach = std::int64_t(std::ceil(halo));
  const double total = double(in.last - in.first), seeds = double(in.lastSeed - in.firstSeed);
  const double leftShare = double(leftParts) / parts, rightShare = 1.0 - leftShare;
  Cut best;
  double bestCost = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const int planes = extent[axis];
    if (planes < 2) continue;
    // below[i]: centres below plane lower + i; seedsBelow[i] the same for the seeds.
    std::vector<std::int64_t> below = planeCounts(in.first, in.last, axis, lower[axis], planes);
    std::vector<std::int64_t> seedsBelow =
        planeCounts(in.firstSeed, in.lastSeed, axis, lower[axis], planes);
    for (std::size_t i = 1; i < below.size(); ++i) {
      below[i] += below[i - 1];
      seedsBelow[i] += seedsBelow[i - 1];
    }
    for (int i = 1; i < planes; ++i) {
      const double left = double(below[std::size_t(std::min<std::int64_t>(i + reach, planes))]);
      const double right = total - double(below[std::size_t(std::max<std::int64_t>(i - reach, 0))]);
      double cost = std::max(left / leftParts, right / (parts - leftParts));
      if (seeds > 0.0) {
        const double seedsLeft = double(seedsBelow[std::size_t(i)]);
        cost =
            std::max({left / (total * leftShare), right / (total * rightShare),
                      seedsLeft / (seeds * leftShare), (seeds - seedsLeft) / (seeds * rightShare)});
      }
      if (cost < bestCost) {
        bestCost = cost;
        best = {axis, lower[axis] + i};
      }
    }
  }
  if (!std::isfinite(bestCost)) return medianCut(in.first, in.last, lower, upper, leftParts, parts);
  return best;
}

void bisect(const InBox& in, glm::ivec3 lower, glm::ivec3 upper, int firstPart, int parts,
            double halo, DataPartition& partition) {
  if (parts == 1) {
    partition.lower[std::size_t(firstPart)] = lower;
    partition.upper[std::size_t(firstPart)] = upper;
    return;
  }
  const int leftParts = parts / 2;
  const Cut cut = haloAwareCut(in, lower, upper, leftParts, parts, halo);
  const int axis = cut.axis, split = cut.plane;
  const auto isBelow = [axis, split](const glm::i64vec3& c) {
    return c[axis] < 2 * std::int64_t(split);
  };
  const auto below = std::partition(in.first, in.last, isBelow);
  const auto seedsBelow = std::partition(in.firstSeed, in.lastSeed, isBelow);
  glm::ivec3 leftUpper = upper, rightLower = lower;
  leftUpper[axis] = split;
  rightLower[axis] = split;
  bisect({in.first, below, in.firstSeed, seedsBelow}, lower, leftUpper, firstPart, leftParts, halo,
         partition);
  bisect({below, in.last, seedsBelow, in.lastSeed}, rightLower, upper, firstPart + leftParts,
         parts - leftParts, halo, partition);
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

DataPartition partitionCells(const bricks::AmrField& field, int parts, double halo,
                             std::span<const glm::dvec3> seeds) {
  Centres centres(field.cellCount());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, centres.size(), std::size_t(1) << 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t i = range.begin(); i != range.end(); ++i)
                        centres[i] = std::int64_t(2) * glm::i64vec3(field.lowers()[i]) +
                                     (std::int64_t(1) << field.levels()[i]);
                    });
  // A seed as a centre: its finest cell's doubled centre, so that it falls on the same side of a
  // cut as the cell holding it.
  Centres seedCentres(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i)
    seedCentres[i] = std::int64_t(2) * glm::i64vec3(glm::floor(seeds[i])) + std::int64_t(1);
  DataPartition partition;
  partition.lower.resize(std::size_t(std::max(parts, 1)));
  partition.upper.resize(partition.lower.size());
  const CellBox bounds = field.bounds();
  bisect({centres.begin(), centres.end(), seedCentres.begin(), seedCentres.end()}, bounds.lower,
         bounds.upper, 0, partition.parts(), halo, partition);
  return partition;
}

}  // namespace amrstream::mpi
