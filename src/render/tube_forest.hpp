#pragma once
// The compute backend's tube BVH (tube_bvh.hpp) made to grow: the segments are kept in chunks,
// each with a BVH of its own, and a small top tree over the chunks' roots is laid out first, so
// that node 0 is the root of the whole and the shader traverses it as one BVH (a node's children
// are adjacent, leaves own contiguous segment ranges). Appending builds a BVH for the new
// segments only, first absorbing the last chunks while they are at most twice as large (a binary
// counter), so that chunks stay few and only the tail of the arrays changes.

#include <cstddef>
#include <span>
#include <vector>

#include "../../shaders/glsl/shared/render_types.h"

namespace amrstream::render {

class TubeForest {
 public:
  static constexpr std::size_t kMaxChunks = 48;
  // Room for the top tree: per top node, its two children and itself.
  static constexpr std::size_t kTopNodes = 4 * kMaxChunks;

  // One chunk of all the segments.
  void reset(std::span<const shared::TubeSegment> segments, float radius);
  // Appends `added` (a new chunk, merged with the last ones). Returns false, changing nothing,
  // when that would make more than kMaxChunks chunks.
  bool append(std::span<const shared::TubeSegment> added, float radius);

  // Segments in the order the leaves own them, and the nodes (node 0 is the root; none without
  // segments).
  const std::vector<shared::TubeSegment>& segments() const { return segments_; }
  const std::vector<shared::TubeBvhNode>& nodes() const { return nodes_; }
  std::size_t chunks() const { return chunks_.size(); }
  // What the last reset or append changed: segments from this one on, nodes from this one on,
  // and the top tree (nodes [0, kTopNodes)).
  std::size_t firstChangedSegment() const { return changedSegment_; }
  std::size_t firstChangedNode() const { return changedNode_; }

 private:
  struct Chunk {
    std::size_t firstSegment, segmentCount, firstNode, nodeCount;
  };
  // Builds the last chunk over segments_[from, end) with its nodes from node `nodeBase` on.
  void buildChunk(std::size_t from, std::size_t nodeBase, float radius);
  // Lays the top tree over the chunks' roots out in nodes [0, 2 * chunks - 1).
  void buildTop();
  std::size_t topNode(std::size_t firstChunk, std::size_t lastChunk, std::size_t& next);

  std::vector<shared::TubeSegment> segments_;
  std::vector<shared::TubeBvhNode> nodes_;
  std::vector<Chunk> chunks_;
  std::size_t changedSegment_ = 0, changedNode_ = 0;
};

}  // namespace amrstream::render
