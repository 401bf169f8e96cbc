#pragma once
// The kernels that follow a tracing round on every backend, all plain compute: the compaction of
// the round's output (scan_lines, scan_blocks, compact_round: one descriptor layout, push
// constants shared::CompactionParams) and the point data at the compacted points (point_data,
// push constants shared::PointDataParams). Their bindings are named in
// shaders/glsl/shared/round_bindings.h.

#include <vulkan/vulkan.h>

#include <cstdint>

#include "vk/buffer.hpp"
#include "vk/unique_handle.hpp"
#include "volume_buffers.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::gpu {

struct RoundKernels {
  vk::UniqueHandle<VkDescriptorSetLayout> compactionSetLayout;
  vk::UniqueHandle<VkPipelineLayout> compactionLayout;
  vk::UniqueHandle<VkPipeline> scanLines, scanBlocks, compact;
  vk::UniqueHandle<VkDescriptorSetLayout> pointDataSetLayout;
  vk::UniqueHandle<VkPipelineLayout> pointDataLayout;
  vk::UniqueHandle<VkPipeline> pointData;
};

RoundKernels createRoundKernels(const vk::Context& ctx);

// The point data kernel alone (pathlines sample their snapshots' channels with it).
struct PointDataKernel {
  vk::UniqueHandle<VkDescriptorSetLayout> setLayout;
  vk::UniqueHandle<VkPipelineLayout> layout;
  vk::UniqueHandle<VkPipeline> pipeline;
};

PointDataKernel createPointDataKernel(const vk::Context& ctx);

// What the point data kernel reads besides the volume, and writes.
struct PointDataTargets {
  const vk::Buffer& summary;  // shared::RoundSummary: the point count
  const vk::Buffer& positions;
  const vk::Buffer& regionIds;
  const vk::Buffer& channels;
  const vk::Buffer& vorticity;
};

// Points the kernel's set at the volume's copy on the device and at `targets`.
void writePointDataSet(const vk::Context& ctx, VkDescriptorSet set, const VolumeBuffers& device,
                       const PointDataTargets& targets);

}  // namespace amrstream::gpu
