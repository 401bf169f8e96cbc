#include "region_chunk.hpp"

#include <algorithm>
#include <cassert>
#include <cstdlib>
#include <limits>

namespace amrstream::bricks::detail {

namespace {

// A node with at least this many bricks gives its upper child to a new chunk and task.
constexpr std::size_t kSpawnBricks = 4096;

struct Face {
  int axis = -1;  // -1: no domain face strictly inside the box
  int at = 0;
};

// ExaBricks' rule: among the domain faces strictly inside the box, take the widest axis that has
// one and, on it, the face nearest the centre (ties: the lower face, the lower axis).
Face chooseFace(std::span<const std::uint32_t> ids, const std::vector<CellBox>& domains,
                const CellBox& box) {
  constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
  std::int64_t bestDistance[3] = {kNone, kNone, kNone};
  int bestAt[3] = {0, 0, 0};
  const auto consider = [&](int axis, int at) {
    if (at <= box.lower[axis] || at >= box.upper[axis]) return;
    const std::int64_t d = std::abs(2 * std::int64_t(at) - box.lower[axis] - box.upper[axis]);
    if (d < bestDistance[axis] || (d == bestDistance[axis] && at < bestAt[axis])) {
      bestDistance[axis] = d;
      bestAt[axis] = at;
    }
  };
  for (const std::uint32_t id : ids) {
    const CellBox& d = domains[id];
    for (int axis = 0; axis < 3; ++axis) {
      consider(axis, d.lower[axis]);
      consider(axis, d.upper[axis]);
    }
  }
  Face face;
  const glm::i64vec3 extent = glm::i64vec3(box.upper) - glm::i64vec3(box.lower);  // past 2^31
  for (int axis = 0; axis < 3; ++axis)
    if (bestDistance[axis] != kNone && (face.axis < 0 || extent[axis] > extent[face.axis]))
      face = {axis, bestAt[axis]};
  return face;
}

// A node waiting to be built. Lists of pending nodes are stacked in one buffer in the order of
// the node stack, so the top node's list is buffer[begin, buffer.size()).
struct Pending {
  std::uint32_t node;
  CellBox box;
  std::size_t begin;
};

class ChunkBuilder {
 public:
  ChunkBuilder(RegionChunk& chunk, const RegionInputs& inputs, tbb::task_group& tasks)
      : chunk_(chunk), inputs_(inputs), tasks_(tasks) {}

  void run(CellBox box, std::span<const std::uint32_t> brickIds) {
    chunk_.nodes.push_back({});
    ids_.assign(brickIds.begin(), brickIds.end());
    stack_.push_back({0, box, 0});
    while (!stack_.empty()) {
      const Pending item = stack_.back();
      stack_.pop_back();
      build(item);
    }
  }

 private:
  void build(const Pending& item) {
    const std::span<const std::uint32_t> list(ids_.data() + item.begin, ids_.size() - item.begin);
    const Face face = chooseFace(list, inputs_.domains, item.box);
    if (face.axis < 0) {
      makeLeaf(item);
      return;
    }
    // The lists only hold domains that overlap the box, so each goes to at least one side.
    lowerIds_.clear();
    upperIds_.clear();
    for (const std::uint32_t id : list) {
      const CellBox& d = inputs_.domains[id];
      if (d.lower[face.axis] < face.at) lowerIds_.push_back(id);
      if (d.upper[face.axis] > face.at) upperIds_.push_back(id);
    }
    const bool spawn = list.size() >= kSpawnBricks;
    ids_.resize(item.begin);

    const auto child = std::uint32_t(chunk_.nodes.size());
    chunk_.nodes[item.node] = {face.at, std::uint32_t(face.axis), child};
    chunk_.nodes.resize(child + 2);
    CellBox lowerBox = item.box, upperBox = item.box;
    lowerBox.upper[face.axis] = face.at;
    upperBox.lower[face.axis] = face.at;

    if (spawn) {
      auto sub = std::make_unique<RegionChunk>();
      sub->stubInParent = child + 1;
      chunk_.nodes[child + 1] = {0, kChunkStubAxis, std::uint32_t(chunk_.children.size())};
      RegionChunk* target = sub.get();
      chunk_.children.push_back(std::move(sub));
      tasks_.run(
          [target, &inputs = inputs_, &tasks = tasks_, upperBox, list = std::move(upperIds_)] {
            buildRegionChunk(*target, inputs, upperBox, list, tasks);
          });
      upperIds_ = {};
    } else {
      stack_.push_back({child + 1, upperBox, ids_.size()});
      ids_.insert(ids_.end(), upperIds_.begin(), upperIds_.end());
    }
    stack_.push_back({child, lowerBox, ids_.size()});
    ids_.insert(ids_.end(), lowerIds_.begin(), lowerIds_.end());
  }

  // Every listed domain contains the box: none has a face strictly inside, and all overlap it.
  // Lists are sorted by brick id: the root's is, and splitting keeps the order.
  void makeLeaf(const Pending& item) {
    shared::RegionTreeNode& node = chunk_.nodes[item.node];
    node = {0, AMRSTREAM_TREE_LEAF, AMRSTREAM_NO_REGION};
    if (ids_.size() > item.begin) {
      const auto first = ids_.begin() + std::ptrdiff_t(item.begin);
      assert(std::is_sorted(first, ids_.end()));
      float width = std::numeric_limits<float>::infinity();
      for (auto it = first; it != ids_.end(); ++it)
        width = std::min(width, inputs_.cellWidths[*it]);
      node.child = std::uint32_t(chunk_.regions.size());
      chunk_.regions.push_back({item.box.lower, std::uint32_t(chunk_.regionBricks.size()),
                                item.box.upper, std::uint32_t(ids_.end() - first), width});
      chunk_.regionBricks.insert(chunk_.regionBricks.end(), first, ids_.end());
    }
    ids_.resize(item.begin);
  }

  RegionChunk& chunk_;
  const RegionInputs& inputs_;
  std::vector<Pending> stack_;
  std::vector<std::uint32_t> ids_;
  std::vector<std::uint32_t> lowerIds_, upperIds_;
  tbb::task_group& tasks_;
};

}  // namespace

void buildRegionChunk(RegionChunk& chunk, const RegionInputs& inputs, CellBox box,
                      std::span<const std::uint32_t> brickIds, tbb::task_group& tasks) {
  ChunkBuilder(chunk, inputs, tasks).run(box, brickIds);
}

}  // namespace amrstream::bricks::detail
