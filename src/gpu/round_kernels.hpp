#pragma once
// The kernels that follow a tracing round on every backend, all plain compute: the compaction of
// the round's output (scan_lines, scan_blocks, compact_round: one descriptor layout, push
// constants shared::CompactionParams) and the point data at the compacted points (point_data,
// push constants shared::PointDataParams). Their bindings are named in
// shaders/glsl/shared/round_bindings.h.

#include <vulkan/vulkan.h>

#include <cstdint>

#include "vk/unique_handle.hpp"

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

}  // namespace amrstream::gpu
