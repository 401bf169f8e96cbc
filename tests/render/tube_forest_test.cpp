#include "render/tube_forest.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace amrstream::render {
namespace {

std::vector<shared::TubeSegment> spiral(std::size_t count, std::size_t offset) {
  std::vector<shared::TubeSegment> segments;
  for (std::size_t i = offset; i < offset + count; ++i) {
    const float t = 0.1f * float(i);
    segments.push_back({glm::vec3(std::cos(t), std::sin(t), 0.01f * t) * 10.0f, float(i),
                        glm::vec3(std::cos(t + 0.1f), std::sin(t + 0.1f), 0.01f * t) * 10.0f,
                        float(i)});
  }
  return segments;
}

bool inside(const shared::TubeBvhNode& node, glm::vec3 lower, glm::vec3 upper) {
  return glm::all(glm::lessThanEqual(node.lower, lower)) &&
         glm::all(glm::greaterThanEqual(node.upper, upper));
}

// Walks the forest from node 0 as the shader does: every segment is in exactly one leaf reached,
// and every box holds what is under it.
void expectOneBvh(const TubeForest& forest, float radius) {
  const std::vector<shared::TubeBvhNode>& nodes = forest.nodes();
  const std::vector<shared::TubeSegment>& segments = forest.segments();
  std::vector<int> seen(segments.size(), 0);
  std::vector<std::size_t> stack{0};
  while (!stack.empty()) {
    const shared::TubeBvhNode node = nodes[stack.back()];
    stack.pop_back();
    if (node.count > 0) {
      for (std::size_t i = node.first; i < node.first + node.count; ++i) {
        ASSERT_LT(i, segments.size());
        ++seen[i];
        const shared::TubeSegment& s = segments[i];
        EXPECT_TRUE(inside(node, glm::min(s.a, s.b) - radius, glm::max(s.a, s.b) + radius));
      }
      continue;
    }
    ASSERT_LT(node.first + 1, nodes.size());
    for (std::size_t child = node.first; child < node.first + 2; ++child) {
      EXPECT_TRUE(inside(node, nodes[child].lower, nodes[child].upper));
      stack.push_back(child);
    }
  }
  for (std::size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 1) << "segment " << i;
}

TEST(TubeForest, AppendsStayOneBvhOverEverySegmentInFewChunks) {
  TubeForest forest;
  forest.reset(spiral(5, 0), 0.5f);
  expectOneBvh(forest, 0.5f);
  std::size_t count = 5, mostChunks = 1;
  for (int round = 0; round < 200; ++round) {
    const std::size_t added = 1 + std::size_t(round % 7) * 13;
    ASSERT_TRUE(forest.append(spiral(added, count), 0.5f));
    count += added;
    ASSERT_EQ(forest.segments().size(), count);
    EXPECT_LE(forest.firstChangedSegment(), count - added);
    mostChunks = std::max(mostChunks, forest.chunks());
    if (round % 37 == 0) expectOneBvh(forest, 0.5f);
  }
  expectOneBvh(forest, 0.5f);
  // The binary counter keeps chunks to about log2 of the appends.
  EXPECT_LE(mostChunks, 16u);
  EXPECT_GT(mostChunks, 1u);
}

TEST(TubeForest, AnEmptyForestTakesItsFirstSegmentsWhole) {
  TubeForest forest;
  forest.reset({}, 1.0f);
  EXPECT_TRUE(forest.nodes().empty());
  ASSERT_TRUE(forest.append(spiral(3, 0), 1.0f));
  EXPECT_EQ(forest.chunks(), 1u);
  expectOneBvh(forest, 1.0f);
}

}  // namespace
}  // namespace amrstream::render
