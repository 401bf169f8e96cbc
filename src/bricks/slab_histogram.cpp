#include "slab_histogram.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cstdlib>
#include <vector>

namespace amrstream::bricks::detail {

namespace {

using U64 = std::uint64_t;

// The cells of one slab: count and bounds on the two other axes, u = axis+1, v = axis+2 (mod 3).
struct Slab {
  std::uint32_t count = 0;
  glm::ivec2 lower{INT_MAX};
  glm::ivec2 upper{INT_MIN};  // exclusive

  void add(glm::ivec2 p) {
    ++count;
    lower = glm::min(lower, p);
    upper = glm::max(upper, p + 1);
  }
  void merge(const Slab& o) {
    count += o.count;
    lower = glm::min(lower, o.lower);
    upper = glm::max(upper, o.upper);
  }
  U64 area() const { return U64(upper.x - lower.x) * U64(upper.y - lower.y); }
};

struct Histograms {
  std::vector<Slab> slabs[3];  // per axis, one per slab of the node
};

struct Candidate {
  U64 waste = ~U64(0);
  int alignment = 0;
  int extent = 0;             // the node's extent along the plane's axis
  std::int64_t distance = 0;  // twice the distance from the centre, to stay integral
  int axis = -1;
  int slab = 0;  // the plane is at lower[axis] + slab
};

bool better(const Candidate& a, const Candidate& b) {
  if (a.waste != b.waste) return a.waste < b.waste;
  if (a.alignment != b.alignment) return a.alignment > b.alignment;
  if (a.extent != b.extent) return a.extent > b.extent;
  if (a.distance != b.distance) return a.distance < b.distance;
  if (a.axis != b.axis) return a.axis < b.axis;
  return a.slab < b.slab;
}

std::int64_t centreDistance(int slab, int extent) {
  return std::abs(2 * std::int64_t(slab) - extent);
}

// Tight bounds of the cells in slabs [from, to) along `axis`.
GridBounds sideBounds(const std::vector<Slab>& slabs, const GridBounds& node, int axis, int from,
                      int to) {
  Slab side;
  int first = INT_MAX, last = INT_MIN;
  for (int s = from; s < to; ++s) {
    if (slabs[s].count == 0) continue;
    side.merge(slabs[s]);
    first = std::min(first, s);
    last = s;
  }
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  GridBounds out;
  out.lower[axis] = node.lower[axis] + first;
  out.upper[axis] = node.lower[axis] + last + 1;
  out.lower[u] = side.lower.x;
  out.upper[u] = side.upper.x;
  out.lower[v] = side.lower.y;
  out.upper[v] = side.upper.y;
  return out;
}

}  // namespace

HistogramSplit histogramSplit(std::span<const GridCell> cells, const GridBounds& bounds,
                              int maxAlignment) {
  const glm::ivec3 e = bounds.extent();
  // The histograms of large nodes are summed over pieces of the cells in parallel: a slab's
  // count and bounds do not depend on the order its cells come in.
  const auto histograms = [&](std::size_t from, std::size_t to) {
    Histograms h;
    for (int axis = 0; axis < 3; ++axis) h.slabs[axis].assign(std::size_t(e[axis]), Slab{});
    for (std::size_t i = from; i < to; ++i) {
      const GridCell& c = cells[i];
      const glm::ivec3 g = c.g - bounds.lower;
      h.slabs[0][g.x].add({c.g.y, c.g.z});
      h.slabs[1][g.y].add({c.g.z, c.g.x});
      h.slabs[2][g.z].add({c.g.x, c.g.y});
    }
    return h;
  };
  constexpr std::size_t kPiece = std::size_t(1) << 18;
  const std::size_t slabCount = std::size_t(e.x) + std::size_t(e.y) + std::size_t(e.z);
  Histograms all;
  if (cells.size() < 2 * kPiece || slabCount * 8 > cells.size()) {
    all = histograms(0, cells.size());
  } else {
    const std::size_t pieces = (cells.size() + kPiece - 1) / kPiece;
    std::vector<Histograms> parts(pieces);
    tbb::parallel_for(std::size_t(0), pieces, [&](std::size_t p) {
      parts[p] = histograms(p * kPiece, std::min(cells.size(), (p + 1) * kPiece));
    });
    all = std::move(parts[0]);
    tbb::parallel_for(0, 3, [&](int axis) {
      for (std::size_t p = 1; p < pieces; ++p)
        for (std::size_t s = 0; s < all.slabs[axis].size(); ++s)
          all.slabs[axis][s].merge(parts[p].slabs[axis][s]);
    });
  }
  std::vector<Slab>(&slabs)[3] = all.slabs;

  Candidate gap;
  for (int axis = 0; axis < 3; ++axis)
    for (int s = 1; s < e[axis] - 1; ++s)  // the end slabs of tight bounds are never empty
      if (slabs[axis][s].count == 0) {
        const Candidate c{0, 0, e[axis], centreDistance(s, e[axis]), axis, s};
        if (better(c, gap)) gap = c;
      }

  Candidate best = gap;
  std::vector<Slab> suffix;
  for (int axis = 0; axis < 3 && gap.axis < 0; ++axis) {
    const int n = e[axis];
    suffix.assign(std::size_t(n) + 1, Slab{});
    for (int s = n - 1; s >= 0; --s) {
      suffix[s] = slabs[axis][s];
      suffix[s].merge(suffix[s + 1]);
    }
    // Without gaps a side's extent along the axis is its number of slabs.
    Slab below;
    for (int s = 1; s < n; ++s) {
      below.merge(slabs[axis][s - 1]);
      const U64 waste = U64(s) * below.area() + U64(n - s) * suffix[s].area() - cells.size();
      const int at = bounds.lower[axis] + s;
      const int alignment =
          at == 0 ? maxAlignment : std::min(std::countr_zero(unsigned(at)), maxAlignment);
      const Candidate c{waste, alignment, n, centreDistance(s, n), axis, s};
      if (better(c, best)) best = c;
    }
  }

  const std::vector<Slab>& chosen = slabs[best.axis];
  return {{best.axis, bounds.lower[best.axis] + best.slab},
          sideBounds(chosen, bounds, best.axis, 0, best.slab),
          sideBounds(chosen, bounds, best.axis, best.slab, e[best.axis])};
}

}  // namespace amrstream::bricks::detail
