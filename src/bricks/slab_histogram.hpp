#pragma once
// Private to the brick splitter: the split-plane choice from per-slab histograms of a node's
// cells (a slab is a layer one cell thick across an axis).

#include <span>

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

struct HistogramSplit {
  SplitPlane plane;
  GridBounds lower;  // tight bounds of both sides, read off the histograms
  GridBounds upper;
};

// For cells that do not fill their tight bounds: the empty slab nearest the centre of the
// longest axis that has one, otherwise the plane of least waste (bounding-box volume minus cell
// count, summed over both sides). Ties in waste go to planes on power-of-two boundaries up to
// 2^maxAlignment (where AMR codes put block faces), then to the longer axis, then to the plane
// nearest the centre. One pass over the cells plus O(extent).
HistogramSplit histogramSplit(std::span<const GridCell> cells, const GridBounds& bounds,
                              int maxAlignment);

}  // namespace amrstream::bricks::detail
