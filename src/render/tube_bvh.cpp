#include "tube_bvh.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <map>
#include <numeric>

namespace amrstream::render {

namespace {

struct Bounds {
  glm::vec3 lower{std::numeric_limits<float>::infinity()};
  glm::vec3 upper{-std::numeric_limits<float>::infinity()};
  void grow(glm::vec3 p) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
};

class Builder {
 public:
  Builder(std::span<const shared::TubeSegment> segments, float radius)
      : segments_(segments), radius_(radius), order_(segments.size()) {
    std::iota(order_.begin(), order_.end(), 0u);
  }

  TubeBvh build() {
    TubeBvh bvh;
    if (segments_.empty()) return bvh;
    const auto n = static_cast<std::uint32_t>(segments_.size());
    bvh.nodes.resize(nodeCount(n));
    fill(bvh.nodes, 0, 0, n, 1);
    bvh.segments.resize(segments_.size());
    tbb::parallel_for(std::size_t(0), order_.size(),
                      [&](std::size_t k) { bvh.segments[k] = segments_[order_[k]]; });
    return bvh;
  }

 private:
  glm::vec3 centre(std::uint32_t i) const { return 0.5f * (segments_[i].a + segments_[i].b); }

  // Nodes of the subtree over `count` segments (the split depends on the count alone).
  std::size_t nodeCount(std::uint32_t count) {
    if (count <= kLeafSize) return 1;
    const auto known = counts_.find(count);
    if (known != counts_.end()) return known->second;
    const std::size_t nodes = 1 + nodeCount(count / 2) + nodeCount(count - count / 2);
    counts_.emplace(count, nodes);
    return nodes;
  }

  // Node `index` covers order_[first, last); its descendants take the nodes from `next` on: its
  // two children, then the left child's descendants, then the right's (the layout of a
  // depth-first build). Large subtrees are built in parallel; each writes only its own nodes and
  // its own range of order_, so the result does not depend on the threads.
  void fill(std::vector<shared::TubeBvhNode>& nodes, std::size_t index, std::uint32_t first,
            std::uint32_t last, std::size_t next) {
    Bounds box, centres;
    for (std::uint32_t k = first; k < last; ++k) {
      const shared::TubeSegment& s = segments_[order_[k]];
      box.grow(glm::min(s.a, s.b) - radius_);
      box.grow(glm::max(s.a, s.b) + radius_);
      centres.grow(centre(order_[k]));
    }
    nodes[index].lower = box.lower;
    nodes[index].upper = box.upper;
    if (last - first <= kLeafSize) {
      nodes[index].first = first;
      nodes[index].count = last - first;
      return;
    }
    const glm::vec3 extent = centres.upper - centres.lower;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t middle = first + (last - first) / 2;
    std::nth_element(order_.begin() + first, order_.begin() + middle, order_.begin() + last,
                     [&](std::uint32_t a, std::uint32_t b) { return centre(a)[axis] < centre(b)[axis]; });
    const std::size_t children = next;
    nodes[index].first = static_cast<std::uint32_t>(children);
    nodes[index].count = 0;
    const std::size_t leftNext = children + 2;
    const std::size_t rightNext = leftNext + nodeCount(middle - first) - 1;
    const auto left = [&] { fill(nodes, children, first, middle, leftNext); };
    const auto right = [&] { fill(nodes, children + 1, middle, last, rightNext); };
    if (last - first > kParallelFrom)
      tbb::parallel_invoke(left, right);
    else
      left(), right();
  }

  static constexpr std::uint32_t kParallelFrom = 1u << 14;

  std::span<const shared::TubeSegment> segments_;
  float radius_;
  std::vector<std::uint32_t> order_;
  std::map<std::uint32_t, std::size_t> counts_;  // filled before the parallel part reads it
};

}  // namespace

TubeBvh buildTubeBvh(std::span<const shared::TubeSegment> segments, float radius) {
  return Builder(segments, radius).build();
}

}  // namespace amrstream::render
