#include "tube_bvh.hpp"

#include <algorithm>
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
    bvh.nodes.reserve(2 * segments_.size() / kLeafSize + 2);
    bvh.nodes.emplace_back();
    fill(bvh.nodes, 0, 0, static_cast<std::uint32_t>(segments_.size()));
    bvh.segments.reserve(segments_.size());
    for (const std::uint32_t i : order_) bvh.segments.push_back(segments_[i]);
    return bvh;
  }

 private:
  glm::vec3 centre(std::uint32_t i) const { return 0.5f * (segments_[i].a + segments_[i].b); }

  // Node `index` covers order_[first, last).
  void fill(std::vector<shared::TubeBvhNode>& nodes, std::size_t index, std::uint32_t first,
            std::uint32_t last) {
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
    const auto children = static_cast<std::uint32_t>(nodes.size());
    nodes[index].first = children;
    nodes[index].count = 0;
    nodes.emplace_back();
    nodes.emplace_back();
    fill(nodes, children, first, middle);
    fill(nodes, children + 1, middle, last);
  }

  std::span<const shared::TubeSegment> segments_;
  float radius_;
  std::vector<std::uint32_t> order_;
};

}  // namespace

TubeBvh buildTubeBvh(std::span<const shared::TubeSegment> segments, float radius) {
  return Builder(segments, radius).build();
}

}  // namespace amrstream::render
