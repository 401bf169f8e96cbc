#pragma once
// The bounding volume hierarchy over tube segments that the `compute` backend traverses
// (shaders/glsl/include/tubes_bvh.glsl): binary, median split of the segment centres along the
// longest axis of their bounds, at most kLeafSize segments per leaf. The split is balanced, so
// the depth stays below the shader's traversal stack for any segment count that fits a buffer.

#include <span>
#include <vector>

#include "../../shaders/glsl/shared/render_types.h"

namespace amrstream::render {

inline constexpr unsigned kLeafSize = 4;

struct TubeBvh {
  std::vector<shared::TubeBvhNode> nodes;     // node 0 is the root
  std::vector<shared::TubeSegment> segments;  // reordered so that leaves own contiguous ranges
};

// Boxes are the segments' bounds grown by `radius`. No segments: no nodes.
TubeBvh buildTubeBvh(std::span<const shared::TubeSegment> segments, float radius);

}  // namespace amrstream::render
