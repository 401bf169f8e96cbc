#include "render_kernel.hpp"

#include <stdexcept>
#include <vector>

#include "render_compute_comp.h"
#include "render_pipeline_rgen.h"
#include "render_rayquery_comp.h"
#include "tube_rchit.h"
#include "tube_rint.h"
#include "tube_rmiss.h"
#include "vk/context.hpp"

namespace amrstream::render {

using vk::spirv;

namespace {

vk::UniqueHandle<VkDescriptorSetLayout> createSetLayout(const vk::Context& ctx,
                                                        gpu::Backend backend,
                                                        VkShaderStageFlags stages) {
  std::vector<VkDescriptorSetLayoutBinding> bindings =
      vk::storageBufferBindings(AMRSTREAM_RENDER_BINDING_COUNT, stages);
  bindings[AMRSTREAM_BINDING_RENDER_PARAMS].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  if (backend != gpu::Backend::Compute)
    bindings[AMRSTREAM_BINDING_RENDER_TUBES].descriptorType =
        VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  return vk::createDescriptorSetLayout(ctx, bindings);
}

}  // namespace

RenderKernel createRenderKernel(const vk::Context& ctx, gpu::Backend backend) {
  if (backend == gpu::Backend::Cpu)
    throw std::invalid_argument("createRenderKernel: the cpu backend has no kernel");
  RenderKernel kernel;
  kernel.backend = backend;
  const bool pipeline = backend == gpu::Backend::Pipeline;
  kernel.bindPoint =
      pipeline ? VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR : VK_PIPELINE_BIND_POINT_COMPUTE;
  const VkShaderStageFlags stages =
      pipeline ? VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_INTERSECTION_BIT_KHR |
                     VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR
               : VK_SHADER_STAGE_COMPUTE_BIT;

  kernel.setLayout = createSetLayout(ctx, backend, stages);
  kernel.pipelineLayout = vk::createPipelineLayout(ctx, kernel.setLayout.get());

  switch (backend) {
    case gpu::Backend::Compute:
      kernel.pipeline = vk::createComputePipeline(ctx, kernel.pipelineLayout.get(),
                                                  spirv(amrstream_spirv_render_compute_comp),
                                                  nullptr, "render pipeline (compute)");
      break;
    case gpu::Backend::RayQuery:
      kernel.pipeline = vk::createComputePipeline(ctx, kernel.pipelineLayout.get(),
                                                  spirv(amrstream_spirv_render_rayquery_comp),
                                                  nullptr, "render pipeline (rayquery)");
      break;
    default: {
      vk::RayTracingPipeline created = vk::createProceduralRayTracingPipeline(
          ctx, kernel.pipelineLayout.get(),
          {spirv(amrstream_spirv_render_pipeline_rgen), spirv(amrstream_spirv_tube_rmiss),
           spirv(amrstream_spirv_tube_rint), spirv(amrstream_spirv_tube_rchit)},
          nullptr, "render pipeline (pipeline)");
      kernel.pipeline = std::move(created.pipeline);
      kernel.bindingTable = std::move(created.bindingTable);
    }
  }
  return kernel;
}

}  // namespace amrstream::render
