#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include "gpu_test.hpp"
#include "vk/aabb_scene.hpp"
#include "vk/tlas_builder.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::testing {
namespace {

using vk::Capability;

std::vector<VkAabbPositionsKHR> randomBoxes(size_t count, uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> corner(-100.0f, 100.0f);
  std::uniform_real_distribution<float> extent(0.01f, 10.0f);
  std::vector<VkAabbPositionsKHR> boxes(count);
  for (auto& b : boxes) {
    b.minX = corner(random);
    b.minY = corner(random);
    b.minZ = corner(random);
    b.maxX = b.minX + extent(random);
    b.maxY = b.minY + extent(random);
    b.maxZ = b.minZ + extent(random);
  }
  return boxes;
}

class AccelerationStructureTest : public GpuTest {
 protected:
  vk::CapabilitySet required() const override { return {Capability::AccelerationStructure}; }

  // Structure of a scene over `count` random boxes with at most `limit` boxes per BLAS.
  void checkScene(size_t count, uint32_t limit, std::vector<uint32_t> expectedFirstBoxes) {
    const auto boxes = randomBoxes(count, static_cast<uint32_t>(count));
    const vk::AabbScene scene = vk::buildAabbScene(ctx(), boxes, "scene", limit);
    EXPECT_EQ(scene.boxCount, count);
    ASSERT_EQ(scene.blases.size(), expectedFirstBoxes.size());
    std::set<VkDeviceAddress> addresses{scene.tlas.deviceAddress()};
    uint32_t covered = 0;
    for (size_t i = 0; i < scene.blases.size(); ++i) {
      const vk::AabbBlas& blas = scene.blases[i];
      EXPECT_EQ(blas.firstBox, expectedFirstBoxes[i]);
      EXPECT_EQ(blas.firstBox, covered);
      EXPECT_LE(blas.boxCount, vk::maxBoxesPerBlas(ctx(), limit));
      covered += blas.boxCount;
      EXPECT_NE(blas.structure.handle(), VK_NULL_HANDLE);
      EXPECT_NE(blas.structure.deviceAddress(), 0u);
      EXPECT_EQ(blas.structure.type(), VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR);
      // Compaction never grows a structure, and what is left is still something.
      EXPECT_GT(blas.structure.size(), 0u);
      EXPECT_LE(blas.structure.size(), blas.buildSize);
      addresses.insert(blas.structure.deviceAddress());
    }
    EXPECT_EQ(covered, count);
    EXPECT_EQ(addresses.size(), scene.blases.size() + 1) << "device addresses must be distinct";
    EXPECT_NE(scene.tlas.handle(), VK_NULL_HANDLE);
    EXPECT_NE(scene.tlas.deviceAddress(), 0u);
    EXPECT_EQ(scene.tlas.type(), VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR);
  }
};

TEST_F(AccelerationStructureTest, OneBox) { checkScene(1, 0, {0}); }

TEST_F(AccelerationStructureTest, ThousandBoxesInOneBlas) { checkScene(1000, 0, {0}); }

TEST_F(AccelerationStructureTest, SplitsAtTheForcedLimit) {
  checkScene(2500, 1000, {0, 1000, 2000});
}

TEST_F(AccelerationStructureTest, LimitIsTheDevicesMaxPrimitiveCount) {
  const uint32_t deviceLimit = ctx().accelerationStructureProperties().maxPrimitiveCount;
  EXPECT_EQ(vk::maxBoxesPerBlas(ctx()), deviceLimit);
  EXPECT_EQ(vk::maxBoxesPerBlas(ctx(), 1000), 1000u);
  EXPECT_EQ(vk::maxBoxesPerBlas(ctx(), UINT32_MAX), deviceLimit);
}

// Uncompacted BLASes, and one TLAS rebuilt in place over changing instance lists (the appended
// tubes' render test traces through it); more instances than it was made for are refused.
TEST_F(AccelerationStructureTest, ATlasBuilderRebuildsOneStructureInPlace) {
  const auto boxes = randomBoxes(300, 5);
  std::vector<vk::AabbBlas> blases =
      vk::buildAabbBlas(ctx(), std::span(boxes).first(100), "first", 0, false);
  ASSERT_EQ(blases.size(), 1u);
  EXPECT_EQ(blases[0].structure.size(), blases[0].buildSize);  // not compacted
  vk::TlasBuilder builder(ctx(), 4, "rebuilt");
  const VkAccelerationStructureKHR handle = builder.build(blases).handle();
  for (vk::AabbBlas& blas : vk::buildAabbBlas(ctx(), std::span(boxes).subspan(100), "more")) {
    blas.firstBox += 100;
    blases.push_back(std::move(blas));
  }
  EXPECT_EQ(builder.build(blases).handle(), handle);
  EXPECT_EQ(blases.back().firstBox, 100u);
  std::vector<vk::AabbBlas> five;
  for (int i = 0; i < 5; ++i)
    for (vk::AabbBlas& blas : vk::buildAabbBlas(ctx(), std::span(boxes).first(10), "one"))
      five.push_back(std::move(blas));
  EXPECT_THROW(builder.build(five), std::length_error);
}

TEST_F(AccelerationStructureTest, EmptyInputGivesAnEmptyTlas) {
  const vk::AabbScene scene = vk::buildAabbScene(ctx(), {}, "empty");
  EXPECT_TRUE(scene.blases.empty());
  EXPECT_EQ(scene.boxCount, 0u);
  EXPECT_NE(scene.tlas.deviceAddress(), 0u);
}

TEST_F(AccelerationStructureTest, SceneCapacityFollowsFromTheCustomIndexWidth) {
  // The last BLAS must start at an id that fits instanceCustomIndex's 24 bits.
  EXPECT_EQ(vk::maxBoxesPerScene(ctx(), 1000), 0xFFFFFFu + 1000u);
  EXPECT_EQ(vk::maxBoxesPerScene(ctx()), 0xFFFFFFu + vk::maxBoxesPerBlas(ctx()));
}

using ComputeOnlyContext = GpuTest;

TEST_F(ComputeOnlyContext, BuildingAnAccelerationStructureNeedsTheCapability) {
  const auto boxes = randomBoxes(4, 1);
  try {
    vk::buildAabbScene(ctx(), boxes, "no capability");
    FAIL() << "expected a VulkanError";
  } catch (const vk::VulkanError& error) {
    EXPECT_NE(std::string(error.what()).find("Capability::AccelerationStructure"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace amrstream::testing
