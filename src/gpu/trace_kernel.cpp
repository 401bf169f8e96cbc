#include "trace_kernel.hpp"

#include <array>
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "locate_probe_compute_comp.h"
#include "locate_probe_pipeline_rgen.h"
#include "locate_probe_rayquery_comp.h"
#include "locate_rchit.h"
#include "locate_rint.h"
#include "locate_rmiss.h"
#include "trace_compute_comp.h"
#include "trace_pipeline_rgen.h"
#include "trace_rayquery_comp.h"
#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/shader_module.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::gpu {

namespace {

constexpr std::uint32_t kPreferredWorkgroupSize = 64;

template <std::size_t N>
std::span<const std::uint32_t> spirv(const std::uint32_t (&words)[N]) {
  return {words, N};
}

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

void createLayouts(const vk::Context& ctx, TraceKernel& kernel) {
  std::array<VkDescriptorSetLayoutBinding, kTraceBindingCount> bindings{};
  for (std::uint32_t i = 0; i < kTraceBindingCount; ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = kernel.stages;
  }
  bindings[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  if (kernel.backend != Backend::Compute)
    bindings[kLocateBinding].descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;

  VkDescriptorSetLayoutCreateInfo setInfo{};

  setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  setInfo.bindingCount = kTraceBindingCount;
  setInfo.pBindings = bindings.data();
  VkDescriptorSetLayout setLayout;
  AMRSTREAM_VK_CHECK(vkCreateDescriptorSetLayout(ctx.device(), &setInfo, nullptr, &setLayout));
  kernel.setLayout = {ctx.device(), setLayout};

  VkPipelineLayoutCreateInfo layoutInfo{};

  layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  VkPipelineLayout pipelineLayout;
  AMRSTREAM_VK_CHECK(vkCreatePipelineLayout(ctx.device(), &layoutInfo, nullptr, &pipelineLayout));
  kernel.pipelineLayout = {ctx.device(), pipelineLayout};
}

// The kernels' specialization constants: 0 the workgroup size (compute kernels), 1 whether
// samples test the previous region first (include/sampler.glsl).
struct SpecializationValues {
  std::uint32_t workgroupSize;
  VkBool32 useRegionHint;
};
constexpr std::array<VkSpecializationMapEntry, 2> kSpecializationEntries{
    {{0, offsetof(SpecializationValues, workgroupSize), sizeof(std::uint32_t)},
     {1, offsetof(SpecializationValues, useRegionHint), sizeof(VkBool32)}}};

void createComputePipeline(const vk::Context& ctx, TraceKernel& kernel,
                           std::span<const std::uint32_t> code, const KernelSettings& settings) {
  const auto module = vk::createShaderModule(ctx, code, "trace kernel");
  kernel.workgroupSize =
      std::min(kPreferredWorkgroupSize, ctx.limits().maxComputeWorkGroupInvocations);
  const SpecializationValues values{kernel.workgroupSize, settings.useRegionHint};
  const VkSpecializationInfo specialization{kSpecializationEntries.size(),
                                            kSpecializationEntries.data(), sizeof(values), &values};
  VkComputePipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  info.stage = {};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module.get();
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = &specialization;
  info.layout = kernel.pipelineLayout.get();
  VkPipeline pipeline;
  AMRSTREAM_VK_CHECK(
      vkCreateComputePipelines(ctx.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  kernel.pipeline = {ctx.device(), pipeline};
}

// Groups: 0 ray generation, 1 miss, 2 the procedural hit group (intersection + closest hit).
void createRayTracingPipeline(const vk::Context& ctx, TraceKernel& kernel,
                              std::span<const std::uint32_t> raygen,
                              const KernelSettings& settings) {
  const auto rgen = vk::createShaderModule(ctx, raygen, "ray generation");
  const auto rmiss =
      vk::createShaderModule(ctx, spirv(amrstream_spirv_locate_rmiss), "locate.rmiss");
  const auto rint = vk::createShaderModule(ctx, spirv(amrstream_spirv_locate_rint), "locate.rint");
  const auto rchit =
      vk::createShaderModule(ctx, spirv(amrstream_spirv_locate_rchit), "locate.rchit");
  const auto stage = [](VkShaderStageFlagBits s, VkShaderModule m) {
    VkPipelineShaderStageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    info.stage = s;
    info.module = m;
    info.pName = "main";
    return info;
  };
  const SpecializationValues values{0, settings.useRegionHint};
  const VkSpecializationInfo specialization{1, &kSpecializationEntries[1], sizeof(values),
                                            &values};
  std::array<VkPipelineShaderStageCreateInfo, 4> stages{
      stage(VK_SHADER_STAGE_RAYGEN_BIT_KHR, rgen.get()),
      stage(VK_SHADER_STAGE_MISS_BIT_KHR, rmiss.get()),
      stage(VK_SHADER_STAGE_INTERSECTION_BIT_KHR, rint.get()),
      stage(VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR, rchit.get())};
  stages[0].pSpecializationInfo = &specialization;
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

  VkRayTracingPipelineCreateInfoKHR info{};

  info.sType = VK_STRUCTURE_TYPE_RAY_TRACING_PIPELINE_CREATE_INFO_KHR;
  info.stageCount = stages.size();
  info.pStages = stages.data();
  info.groupCount = groups.size();
  info.pGroups = groups.data();
  info.maxPipelineRayRecursionDepth = 1;
  info.layout = kernel.pipelineLayout.get();
  VkPipeline pipeline;
  AMRSTREAM_VK_CHECK(ctx.functions().vkCreateRayTracingPipelinesKHR(
      ctx.device(), VK_NULL_HANDLE, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  kernel.pipeline = {ctx.device(), pipeline};

  // Shader binding table: one record per group, each region starting at the base alignment.
  const auto& props = ctx.rayTracingPipelineProperties();
  const VkDeviceSize handleSize = props.shaderGroupHandleSize;
  const VkDeviceSize stride = alignUp(handleSize, props.shaderGroupHandleAlignment);
  const VkDeviceSize regionSize = alignUp(stride, props.shaderGroupBaseAlignment);
  std::vector<std::byte> handles(groups.size() * handleSize);
  AMRSTREAM_VK_CHECK(ctx.functions().vkGetRayTracingShaderGroupHandlesKHR(
      ctx.device(), pipeline, 0, groups.size(), handles.size(), handles.data()));
  ShaderBindingTable& sbt = kernel.bindingTable;
  sbt.buffer = vk::Buffer::upload(
      ctx, 3 * regionSize + props.shaderGroupBaseAlignment,
      VK_BUFFER_USAGE_SHADER_BINDING_TABLE_BIT_KHR | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
      "trace shader binding table");
  const VkDeviceAddress base = alignUp(sbt.buffer.deviceAddress(), props.shaderGroupBaseAlignment);
  const VkDeviceSize skip = base - sbt.buffer.deviceAddress();
  for (std::size_t g = 0; g < groups.size(); ++g)
    std::memcpy(sbt.buffer.mapped().data() + skip + g * regionSize, handles.data() + g * handleSize,
                handleSize);
  sbt.raygen = {base, regionSize, regionSize};
  sbt.miss = {base + regionSize, stride, stride};
  sbt.hit = {base + 2 * regionSize, stride, stride};
}

}  // namespace

KernelSettings defaultKernelSettings(Backend backend) {
  return {.useRegionHint = backend != Backend::Pipeline};
}

TraceKernel createTraceKernel(const vk::Context& ctx, Backend backend, KernelProgram program,
                              const KernelSettings& settings) {
  const bool probe = program == KernelProgram::LocateProbe;
  TraceKernel kernel;
  kernel.backend = backend;
  switch (backend) {
    case Backend::Compute:
    case Backend::RayQuery:
      kernel.bindPoint = VK_PIPELINE_BIND_POINT_COMPUTE;
      kernel.stages = VK_SHADER_STAGE_COMPUTE_BIT;
      createLayouts(ctx, kernel);
      if (backend == Backend::Compute)
        createComputePipeline(ctx, kernel,
                              probe ? spirv(amrstream_spirv_locate_probe_compute_comp)
                                    : spirv(amrstream_spirv_trace_compute_comp),
                              settings);
      else
        createComputePipeline(ctx, kernel,
                              probe ? spirv(amrstream_spirv_locate_probe_rayquery_comp)
                                    : spirv(amrstream_spirv_trace_rayquery_comp),
                              settings);
      break;
    case Backend::Pipeline:
      kernel.bindPoint = VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR;
      kernel.stages = VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_INTERSECTION_BIT_KHR |
                      VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR;
      createLayouts(ctx, kernel);
      createRayTracingPipeline(ctx, kernel,
                               probe ? spirv(amrstream_spirv_locate_probe_pipeline_rgen)
                                     : spirv(amrstream_spirv_trace_pipeline_rgen),
                               settings);
      break;
    case Backend::Cpu:
      throw std::invalid_argument("createTraceKernel: the cpu backend has no kernel");
  }
  vk::setDebugName(ctx, kernel.pipeline.get(),
                   std::string("trace pipeline (") + std::string(backendName(backend)) + ")");
  return kernel;
}

}  // namespace amrstream::gpu
