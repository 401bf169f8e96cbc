#pragma once
// The kernel that copies scattered runs of words into one buffer (shaders/glsl/gather_runs.comp):
// bindings in shaders/glsl/shared/gather_bindings.h, push constants shared::GatherParams.

#include <vulkan/vulkan.h>

#include "../../shaders/glsl/shared/gather_bindings.h"
#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::gpu {

struct GatherKernel {
  vk::UniqueHandle<VkDescriptorSetLayout> setLayout;
  vk::UniqueHandle<VkPipelineLayout> layout;
  vk::UniqueHandle<VkPipeline> pipeline;
};

GatherKernel createGatherKernel(const vk::Context& ctx);

}  // namespace amrstream::gpu
