#include "tube_bvh.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <limits>
#include <map>
#include <memory>

#include "parallel_select.hpp"

namespace amrstream::render {

namespace {

struct Bounds {
  glm::vec3 lower{std::numeric_limits<float>::infinity()};
  glm::vec3 upper{-std::numeric_limits<float>::infinity()};
  void grow(glm::vec3 p) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
  void grow(const Bounds& b) {
    lower = glm::min(lower, b.lower);
    upper = glm::max(upper, b.upper);
  }
};

// A segment as the build sorts it: its box (grown by the radius), its centre and its index.
struct Item {
  glm::vec3 lower, upper, centre;
  std::uint32_t index;
};

// The order a node's split uses: centres along one axis, ties by index (a total order, so that
// the halves do not depend on how the items were arranged).
struct AlongAxis {
  int axis;
  bool operator()(const Item& a, const Item& b) const {
    return a.centre[axis] < b.centre[axis] ||
           (a.centre[axis] == b.centre[axis] && a.index < b.index);
  }
};

// The bounds of the items' boxes and of their centres: on all cores for many items.
std::pair<Bounds, Bounds> boundsOf(std::span<const Item> items) {
  using Both = std::pair<Bounds, Bounds>;
  const auto add = [&](std::size_t from, std::size_t to, Both b) {
    for (std::size_t k = from; k < to; ++k) {
      b.first.grow(items[k].lower);
      b.first.grow(items[k].upper);
      b.second.grow(items[k].centre);
    }
    return b;
  };
  constexpr std::size_t kGrain = std::size_t(1) << 14;
  if (items.size() <= kGrain) return add(0, items.size(), Both{});
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, items.size(), kGrain), Both{},
      [&](const tbb::blocked_range<std::size_t>& r, Both b) { return add(r.begin(), r.end(), b); },
      [](Both a, const Both& b) {
        a.first.grow(b.first);
        a.second.grow(b.second);
        return a;
      });
}

class Builder {
 public:
  Builder(std::span<const shared::TubeSegment> segments, float radius)
      : segments_(segments), items_(segments.size()), scratch_(new Item[segments.size()]) {
    tbb::parallel_for(std::size_t(0), segments.size(), [&](std::size_t i) {
      const shared::TubeSegment& s = segments[i];
      items_[i] = {glm::min(s.a, s.b) - radius, glm::max(s.a, s.b) + radius, 0.5f * (s.a + s.b),
                   static_cast<std::uint32_t>(i)};
    });
  }

  TubeBvh build() {
    TubeBvh bvh;
    if (segments_.empty()) return bvh;
    const auto n = static_cast<std::uint32_t>(segments_.size());
    bvh.nodes.resize(nodeCount(n));
    fill(bvh.nodes, 0, 0, n, 1);
    bvh.segments.resize(segments_.size());
    tbb::parallel_for(std::size_t(0), items_.size(),
                      [&](std::size_t k) { bvh.segments[k] = segments_[items_[k].index]; });
    return bvh;
  }

 private:
  // Nodes of the subtree over `count` segments (the split depends on the count alone).
  std::size_t nodeCount(std::uint32_t count) {
    if (count <= kLeafSize) return 1;
    const auto known = counts_.find(count);
    if (known != counts_.end()) return known->second;
    const std::size_t nodes = 1 + nodeCount(count / 2) + nodeCount(count - count / 2);
    counts_.emplace(count, nodes);
    return nodes;
  }

  // Node `index` covers items_[first, last); its descendants take the nodes from `next` on: its
  // two children, then the left child's descendants, then the right's (the layout of a
  // depth-first build). Large subtrees are built in parallel; each writes only its own nodes and
  // its own range of items_, so the result does not depend on the threads.
  void fill(std::vector<shared::TubeBvhNode>& nodes, std::size_t index, std::uint32_t first,
            std::uint32_t last, std::size_t next) {
    const auto [box, centres] = boundsOf(std::span(items_).subspan(first, last - first));
    nodes[index].lower = box.lower;
    nodes[index].upper = box.upper;
    if (last - first <= kLeafSize) {
      nodes[index].first = first;
      nodes[index].count = last - first;
      return;
    }
    const glm::vec3 extent = centres.upper - centres.lower;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t middle = first + (last - first) / 2;
    parallelNthElement(std::span(items_).subspan(first, last - first), middle - first,
                       AlongAxis{axis}, std::span(scratch_.get() + first, last - first));
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
  std::vector<Item> items_;
  // Where a node's selection moves its items: the node's own range, so that subtrees built in
  // parallel never share a part of it.
  std::unique_ptr<Item[]> scratch_;
  std::map<std::uint32_t, std::size_t> counts_;  // filled before the parallel part reads it
};

}  // namespace

TubeBvh buildTubeBvh(std::span<const shared::TubeSegment> segments, float radius) {
  return Builder(segments, radius).build();
}

}  // namespace amrstream::render
