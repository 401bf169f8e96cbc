#include "pipelines.hpp"

#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/shader_module.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {

namespace {

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

VkPipelineShaderStageCreateInfo stageInfo(VkShaderStageFlagBits stage, VkShaderModule module) {
  VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage = stage;
  info.module = module;
  info.pName = "main";
  return info;
}

}  // namespace

std::vector<VkDescriptorSetLayoutBinding> storageBufferBindings(std::uint32_t count,
                                                                VkShaderStageFlags stages) {
  std::vector<VkDescriptorSetLayoutBinding> bindings(count);
  for (std::uint32_t i = 0; i < count; ++i)
    bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, stages, nullptr};
  return bindings;
}

UniqueHandle<VkDescriptorSetLayout> createDescriptorSetLayout(
    const Context& ctx, std::span<const VkDescriptorSetLayoutBinding> bindings) {
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<std::uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout;
  AMRSTREAM_VK_CHECK(vkCreateDescriptorSetLayout(ctx.device(), &info, nullptr, &layout));
  return {ctx.device(), layout};
}

UniqueHandle<VkPipelineLayout> createPipelineLayout(const Context& ctx,
                                                    VkDescriptorSetLayout setLayout,
                                                    std::uint32_t pushConstantBytes,
                                                    VkShaderStageFlags pushConstantStages) {
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = 1;
  info.pSetLayouts = &setLayout;
  const VkPushConstantRange range{pushConstantStages, 0, pushConstantBytes};
  if (pushConstantBytes > 0) {
    info.pushConstantRangeCount = 1;
    info.pPushConstantRanges = &range;
  }
  VkPipelineLayout layout;
  AMRSTREAM_VK_CHECK(vkCreatePipelineLayout(ctx.device(), &info, nullptr, &layout));
  return {ctx.device(), layout};
}

UniqueHandle<VkPipeline> createComputePipeline(const Context& ctx, VkPipelineLayout layout,
                                               std::span<const std::uint32_t> spirv,
                                               const VkSpecializationInfo* specialization,
                                               std::string_view name) {
  const auto module = createShaderModule(ctx, spirv, name);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = stageInfo(VK_SHADER_STAGE_COMPUTE_BIT, module.get());
  info.stage.pSpecializationInfo = specialization;
  info.layout = layout;
  VkPipeline pipeline;
  AMRSTREAM_VK_CHECK(
      vkCreateComputePipelines(ctx.device(), ctx.pipelineCache(), 1, &info, nullptr, &pipeline));
  setDebugName(ctx, pipeline, std::string(name));
  return {ctx.device(), pipeline};
}

RayTracingPipeline createProceduralRayTracingPipeline(
    const Context& ctx, VkPipelineLayout layout, const ProceduralHitShaders& shaders,
    const VkSpecializationInfo* raygenSpecialization, std::string_view name) {
  const std::string base(name);
  const auto rgen = createShaderModule(ctx, shaders.raygen, base + " ray generation");
  const auto rmiss = createShaderModule(ctx, shaders.miss, base + " miss");
  const auto rint = createShaderModule(ctx, shaders.intersection, base + " intersection");
  const auto rchit = createShaderModule(ctx, shaders.closestHit, base + " closest hit");
  std::array<VkPipelineShaderStageCreateInfo, 4> stages{
      stageInfo(VK_SHADER_STAGE_RAYGEN_BIT_KHR, rgen.get()),
      stageInfo(VK_SHADER_STAGE_MISS_BIT_KHR, rmiss.get()),
      stageInfo(VK_SHADER_STAGE_INTERSECTION_BIT_KHR, rint.get()),
      stageInfo(VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, rchit.get())};
  stages[0].pSpecializationInfo = raygenSpecialization;
  std::array<VkRayTracingShaderGroupCreateInfoKHR, 3> groups{};
  for (auto& g : groups) {
    g.sType = VK_STRUCTURE_TYPE_RAY_TRACING_SHADER_GROUP_CREATE_INFO_KHR;
    g.generalShader = g.closestHitShader = g.anyHitShader = g.intersectionShader =
        VK_SHADER_UNUSED_KHR;
  }
  groups[0].type = groups[1].type = VK_RAY_TRACING_SHADER_GROUP_TYPE_GENERAL_KHR;
  groups[0].generalShader = 0;
  groups[1].generalShader = 1;
  groups[2].type = VK_RAY_TRACING_SHADER_GROUP_TYPE_PROCEDURAL_HIT_GROUP_KHR;
  groups[2].intersectionShader = 2;
  groups[2].closestHitShader = 3;

  VkRayTracingPipelineCreateInfoKHR info{VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR};
  info.stageCount = stages.size();
  info.pStages = stages.data();
  info.groupCount = groups.size();
  info.pGroups = groups.data();
  info.maxPipelineRayRecursionDepth = 1;
  info.layout = layout;
  VkPipeline rawPipeline;
  AMRSTREAM_VK_CHECK(ctx.functions().vkCreateRayTracingPipelinesKHR(
      ctx.device(), VK_NULL_HANDLE, ctx.pipelineCache(), 1, &info, nullptr, &rawPipeline));
  RayTracingPipeline result;
  result.pipeline = {ctx.device(), rawPipeline};
  setDebugName(ctx, rawPipeline, base);

  // One record per group, each region starting at the base alignment.
  const auto& props = ctx.rayTracingPipelineProperties();
  const VkDeviceSize handleSize = props.shaderGroupHandleSize;
  const VkDeviceSize stride = alignUp(handleSize, props.shaderGroupHandleAlignment);
  const VkDeviceSize regionSize = alignUp(stride, props.shaderGroupBaseAlignment);
  std::vector<std::byte> handles(groups.size() * handleSize);
  AMRSTREAM_VK_CHECK(ctx.functions().vkGetRayTracingShaderGroupHandlesKHR(
      ctx.device(), rawPipeline, 0, groups.size(), handles.size(), handles.data()));
  ShaderBindingTable& sbt = result.bindingTable;
  sbt.buffer = Buffer::upload(
      ctx, 3 * regionSize + props.shaderGroupBaseAlignment,
      VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      base + " shader binding table");
  const VkDeviceAddress start = alignUp(sbt.buffer.deviceAddress(), props.shaderGroupBaseAlignment);
  const VkDeviceSize skip = start - sbt.buffer.deviceAddress();
  for (std::size_t g = 0; g < groups.size(); ++g)
    std::memcpy(sbt.buffer.mapped().data() + skip + g * regionSize, handles.data() + g * handleSize,
                handleSize);
  sbt.raygen = {start, regionSize, regionSize};
  sbt.miss = {start + regionSize, stride, stride};
  sbt.hit = {start + 2 * regionSize, stride, stride};
  return result;
}

}  // namespace amrstream::vk
