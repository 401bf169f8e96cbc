#include "tube_forest.hpp"

#include <glm/glm.hpp>

#include "tube_bvh.hpp"

namespace amrstream::render {

void TubeForest::reset(std::span<const shared::TubeSegment> segments, float radius) {
  segments_.assign(segments.begin(), segments.end());
  nodes_.assign(kTopNodes, shared::TubeBvhNode{});
  chunks_.clear();
  changedSegment_ = 0;
  changedNode_ = 0;
  if (segments_.empty()) {
    nodes_.clear();
    return;
  }
  buildChunk(0, kTopNodes, radius);
  buildTop();
}

bool TubeForest::append(std::span<const shared::TubeSegment> added, float radius) {
  if (added.empty()) return true;
  if (chunks_.empty()) {
    std::vector<shared::TubeSegment> all = segments_;
    all.insert(all.end(), added.begin(), added.end());
    reset(all, radius);
    return true;
  }
  const std::size_t count = segments_.size() + added.size();
  std::size_t from = segments_.size(), absorbed = 0;
  while (absorbed < chunks_.size() &&
         chunks_[chunks_.size() - 1 - absorbed].segmentCount <= 2 * (count - from)) {
    from = chunks_[chunks_.size() - 1 - absorbed].firstSegment;
    ++absorbed;
  }
  if (chunks_.size() - absorbed + 1 > kMaxChunks) return false;
  chunks_.resize(chunks_.size() - absorbed);
  const std::size_t nodeBase =
      chunks_.empty() ? kTopNodes : chunks_.back().firstNode + chunks_.back().nodeCount;
  segments_.insert(segments_.end(), added.begin(), added.end());
  buildChunk(from, nodeBase, radius);
  buildTop();
  changedSegment_ = from;
  changedNode_ = nodeBase;
  return true;
}

void TubeForest::buildChunk(std::size_t from, std::size_t nodeBase, float radius) {
  const TubeBvh bvh = buildTubeBvh(std::span(segments_).subspan(from), radius);
  std::copy(bvh.segments.begin(), bvh.segments.end(), segments_.begin() + std::ptrdiff_t(from));
  nodes_.resize(nodeBase);
  for (shared::TubeBvhNode node : bvh.nodes) {
    node.first += static_cast<std::uint32_t>(node.count > 0 ? from : nodeBase);
    nodes_.push_back(node);
  }
  chunks_.push_back({from, segments_.size() - from, nodeBase, bvh.nodes.size()});
}

void TubeForest::buildTop() {
  std::size_t next = 1;
  const std::size_t root = topNode(0, chunks_.size(), next);
  nodes_[0] = nodes_[root];
}

// The node over chunks [firstChunk, lastChunk): a chunk's root itself, or a top node whose two
// children are laid out side by side from `next` on. Returns its index.
std::size_t TubeForest::topNode(std::size_t firstChunk, std::size_t lastChunk, std::size_t& next) {
  if (lastChunk - firstChunk == 1) return chunks_[firstChunk].firstNode;
  const std::size_t children = next;
  next += 2;
  const std::size_t middle = firstChunk + (lastChunk - firstChunk) / 2;
  const std::size_t left = topNode(firstChunk, middle, next);
  const std::size_t right = topNode(middle, lastChunk, next);
  nodes_[children] = nodes_[left];
  nodes_[children + 1] = nodes_[right];
  shared::TubeBvhNode parent{};
  parent.lower = glm::min(nodes_[left].lower, nodes_[right].lower);
  parent.upper = glm::max(nodes_[left].upper, nodes_[right].upper);
  parent.first = static_cast<std::uint32_t>(children);
  parent.count = 0;
  // Parked past the children; the caller copies it where its own parent wants it.
  const std::size_t at = next++;
  nodes_[at] = parent;
  return at;
}

}  // namespace amrstream::render
