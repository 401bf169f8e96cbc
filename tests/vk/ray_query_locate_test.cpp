// Point location through the AABB scene with ray queries: the global id recovered as
// instanceCustomIndex + primitiveIndex must be the box a brute-force search finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "gpu_test.hpp"
#include "locate_points_spv.h"
#include "vk/aabb_scene.hpp"
#include "vk/buffer_transfer.hpp"
#include "vk/commands.hpp"
#include "vk/shader_module.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::testing {
namespace {

struct Point {
  float x, y, z;
};

// Push constants of locate_points.comp (scalar layout).
struct Push {
  uint64_t tlas;
  uint64_t boxes;
  uint64_t points;
  uint64_t results;
  uint32_t count;
};

// Disjoint unit cells of an nx*ny*nz grid, in shuffled order so ids do not follow positions.
std::vector<VkAabbPositionsKHR> shuffledGridCells(int nx, int ny, int nz, size_t count,
                                                  std::mt19937& random) {
  std::vector<VkAabbPositionsKHR> cells;
  for (int z = 0; z < nz; ++z) {
    for (int y = 0; y < ny; ++y) {
      for (int x = 0; x < nx; ++x) {
        cells.push_back({float(x), float(y), float(z), float(x + 1), float(y + 1), float(z + 1)});
      }
    }
  }
  std::shuffle(cells.begin(), cells.end(), random);
  cells.resize(count);
  return cells;
}

int bruteForceLocate(const std::vector<VkAabbPositionsKHR>& boxes, Point p) {
  for (size_t i = 0; i < boxes.size(); ++i) {
    const auto& b = boxes[i];
    if (p.x >= b.minX && p.x < b.maxX && p.y >= b.minY && p.y < b.maxY && p.z >= b.minZ &&
        p.z < b.maxZ) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

class RayQueryLocate : public GpuTest {
 protected:
  vk::CapabilitySet required() const override { return {vk::Capability::RayQuery}; }

  std::vector<int32_t> locate(const vk::AabbScene& scene, const vk::Buffer& boxes,
                              const std::vector<Point>& points) {
    const vk::Context& c = ctx();
    const VkBufferUsageFlags storage =
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
    const vk::Buffer pointBuffer = vk::uploadToDeviceLocal(c, points, storage, "points");
    const vk::Buffer results = vk::Buffer::deviceLocal(
        c, points.size() * sizeof(int32_t), storage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, "results");

    const auto module = vk::createShaderModule(c, locate_points_spv, "locate_points");
    const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push)};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.pushConstantRangeCount = 1;
    layoutInfo.pPushConstantRanges = &range;
    VkPipelineLayout rawLayout = VK_NULL_HANDLE;
    AMRSTREAM_VK_CHECK(vkCreatePipelineLayout(c.device(), &layoutInfo, nullptr, &rawLayout));
    const vk::UniqueHandle<VkPipelineLayout> layout(c.device(), rawLayout);

    VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = module.get();
    pipelineInfo.stage.pName = "main";
    pipelineInfo.layout = layout.get();
    VkPipeline rawPipeline = VK_NULL_HANDLE;
    AMRSTREAM_VK_CHECK(vkCreateComputePipelines(c.device(), VK_NULL_HANDLE, 1, &pipelineInfo,
                                                nullptr, &rawPipeline));
    const vk::UniqueHandle<VkPipeline> pipeline(c.device(), rawPipeline);

    const Push push{scene.tlas.deviceAddress(), boxes.deviceAddress(), pointBuffer.deviceAddress(),
                    results.deviceAddress(), static_cast<uint32_t>(points.size())};
    vk::submitAndWait(c, [&](VkCommandBuffer cmd) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.get());
      vkCmdPushConstants(cmd, layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(Push), &push);
      vkCmdDispatch(cmd, (push.count + 63) / 64, 1, 1);
    });
    return vk::readBackAs<int32_t>(c, results);
  }
};

TEST_F(RayQueryLocate, GlobalIdsAcrossSplitBlasesMatchBruteForce) {
  std::mt19937 random(7);
  const auto cells = shuffledGridCells(14, 14, 13, 2500, random);
  const vk::AabbScene scene = vk::buildAabbScene(ctx(), cells, "cells", 1000);
  ASSERT_EQ(scene.blases.size(), 3u);
  const vk::Buffer boxes = vk::uploadToDeviceLocal(
      ctx(), cells, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      "cells");

  std::vector<Point> points;
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_int_distribution<size_t> pick(0, cells.size() - 1);
  for (int i = 0; i < 3000; ++i) {  // strictly inside a random cell
    const auto& b = cells[pick(random)];
    points.push_back({b.minX + 0.05f + 0.9f * unit(random), b.minY + 0.05f + 0.9f * unit(random),
                      b.minZ + 0.05f + 0.9f * unit(random)});
  }
  for (int i = 0; i < 500; ++i) {  // on a cell's lower corner: belongs to that cell
    const auto& b = cells[pick(random)];
    points.push_back({b.minX, b.minY, b.minZ});
  }
  for (int i = 0; i < 500; ++i) {  // outside the grid
    points.push_back({-1.0f - 5.0f * unit(random), 20.0f * unit(random), 20.0f * unit(random)});
  }

  const std::vector<int32_t> found = locate(scene, boxes, points);
  ASSERT_EQ(found.size(), points.size());
  size_t mismatches = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const int expected = bruteForceLocate(cells, points[i]);
    if (found[i] != expected && ++mismatches <= 10) {
      ADD_FAILURE() << "point " << i << " (" << points[i].x << ", " << points[i].y << ", "
                    << points[i].z << "): found " << found[i] << ", expected " << expected;
    }
  }
  EXPECT_EQ(mismatches, 0u);
}

}  // namespace
}  // namespace amrstream::testing
