#pragma once
// The kernel that copies scattered runs of words into one buffer (shaders/glsl/gather_runs.comp):
// bindings 0 the source, 1 the target, 2 the regions (shared::GatherRegion); push constants
// shared::GatherParams.

#include <vulkan/vulkan.h>

#include <cstdint>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::gpu {

inline constexpr std::uint32_t kGatherBindingCount = 3;

struct GatherKernel {
  vk::UniqueHandle<VkDescriptorSetLayout> setLayout;
  vk::UniqueHandle<VkPipelineLayout> layout;
  vk::UniqueHandle<VkPipeline> pipeline;
};

GatherKernel createGatherKernel(const vk::Context& ctx);

}  // namespace amrstream::gpu
