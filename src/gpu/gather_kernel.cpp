#include "gather_kernel.hpp"

#include <array>

#include "../../shaders/glsl/shared/gather_params.h"
#include "gather_runs_comp.h"
#include "vk/pipelines.hpp"

namespace amrstream::gpu {

GatherKernel createGatherKernel(const vk::Context& ctx) {
  std::array<VkDescriptorSetLayoutBinding, kGatherBindingCount> bindings{};
  for (std::uint32_t i = 0; i < kGatherBindingCount; ++i)
    bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  GatherKernel k;
  k.setLayout = vk::createDescriptorSetLayout(ctx, bindings);
  k.layout = vk::createPipelineLayout(ctx, k.setLayout.get(), sizeof(shared::GatherParams),
                                      VK_SHADER_STAGE_COMPUTE_BIT);
  k.pipeline = vk::createComputePipeline(
      ctx, k.layout.get(), vk::spirv(amrstream_spirv_gather_runs_comp), nullptr, "gather runs");
  return k;
}

}  // namespace amrstream::gpu
