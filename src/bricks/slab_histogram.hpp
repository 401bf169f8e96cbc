#pragma once
// Private to the brick splitter: the split-plane choice from per-slab histograms of a node's
// cells (a slab is a layer one cell thick across an axis).

#include <climits>
#include <cstdint>
#include <span>
#include <vector>

#include "brick_splitter.hpp"

namespace amrstream::bricks::detail {

// Tight bounds of a set of cells in level-grid coordinates, upper exclusive.
struct GridBounds {
  glm::ivec3 lower{0};
  glm::ivec3 upper{0};
  glm::ivec3 extent() const { return upper - lower; }
  bool operator==(const GridBounds&) const = default;
};

struct SplitPlane {
  int axis = 0;
  int at = 0;  // cells with g[axis] < at go to the lower side
};

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
  std::uint64_t area() const {
    return std::uint64_t(upper.x - lower.x) * std::uint64_t(upper.y - lower.y);
  }
};

// A node's histogram along one axis, one slab per cell of its extent there.
struct AxisSlabs {
  int axis = 0;
  std::vector<Slab> slabs;
};

struct HistogramSplit {
  SplitPlane plane;
  GridBounds lower;  // tight bounds of both sides, read off the histograms
  GridBounds upper;
  // The sides' histograms along the plane's axis: the parent's slabs on each side, which a
  // side's own split need not count again.
  AxisSlabs lowerSlabs, upperSlabs;
};

// For cells that do not fill their tight bounds: the empty slab nearest the centre of the
// longest axis that has one, otherwise the plane of least waste (bounding-box volume minus cell
// count, summed over both sides). Ties in waste go to planes on power-of-two boundaries up to
// 2^maxAlignment (where AMR codes put block faces), then to the longer axis, then to the plane
// nearest the centre. One pass over the cells plus O(extent). `known`, when given, is the
// node's histogram along its axis (the parent's side), which the pass then does not count.
HistogramSplit histogramSplit(std::span<const GridCell> cells, const GridBounds& bounds,
                              int maxAlignment, const AxisSlabs* known = nullptr);

}  // namespace amrstream::bricks::detail
