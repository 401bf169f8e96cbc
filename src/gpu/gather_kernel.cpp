#include "gather_kernel.hpp"

#include "../../shaders/glsl/shared/gather_params.h"
#include "gather_runs_comp.h"
#include "vk/pipelines.hpp"

namespace amrstream::gpu {

GatherKernel createGatherKernel(const vk::Context& ctx) {
  GatherKernel k;
  k.setLayout = vk::createDescriptorSetLayout(
      ctx, vk::storageBufferBindings(AMRSTREAM_GATHER_BINDING_COUNT, VK_SHADER_STAGE_COMPUTE_BIT));
  k.layout = vk::createPipelineLayout(ctx, k.setLayout.get(), sizeof(shared::GatherParams),
                                      VK_SHADER_STAGE_COMPUTE_BIT);
  k.pipeline = vk::createComputePipeline(
      ctx, k.layout.get(), vk::spirv(amrstream_spirv_gather_runs_comp), nullptr, "gather runs");
  return k;
}

}  // namespace amrstream::gpu
