#pragma once
// The rendering kernel of one backend: the descriptor set layout of
// shaders/glsl/shared/render_bindings.h (the tubes' BVH for `compute` at
// AMRSTREAM_BINDING_RENDER_TUBES, their acceleration structure otherwise), the pipeline, and for
// `pipeline` its binding table.

#include <vulkan/vulkan.h>

#include <cstdint>

#include "../../shaders/glsl/shared/render_bindings.h"
#include "gpu/backend.hpp"
#include "vk/pipelines.hpp"
#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::render {

// Compute kernels run 8x8 pixel workgroups (render_*.comp).
inline constexpr std::uint32_t kRenderTileSize = 8;

struct RenderKernel {
  gpu::Backend backend = gpu::Backend::Compute;
  VkPipelineBindPoint bindPoint = VK_PIPELINE_BIND_POINT_COMPUTE;
  vk::UniqueHandle<VkDescriptorSetLayout> setLayout;
  vk::UniqueHandle<VkPipelineLayout> pipelineLayout;
  vk::UniqueHandle<VkPipeline> pipeline;
  vk::ShaderBindingTable bindingTable;  // pipeline backend only
};

// Throws std::invalid_argument for gpu::Backend::Cpu.
RenderKernel createRenderKernel(const vk::Context& ctx, gpu::Backend backend);

}  // namespace amrstream::render
