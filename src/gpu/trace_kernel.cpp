#include "trace_kernel.hpp"

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "grid_probe_compute_comp.h"
#include "grid_probe_pipeline_rgen.h"
#include "grid_probe_rayquery_comp.h"
#include "locate_probe_compute_comp.h"
#include "locate_probe_pipeline_rgen.h"
#include "locate_probe_rayquery_comp.h"
#include "locate_rchit.h"
#include "locate_rint.h"
#include "locate_rmiss.h"
#include "trace_compute_comp.h"
#include "trace_compute_compact_comp.h"
#include "trace_pipeline_rgen.h"
#include "trace_rayquery_comp.h"
#include "vk/context.hpp"
#include "volume_buffers.hpp"

namespace amrstream::gpu {

using vk::spirv;

namespace {

constexpr std::uint32_t kPreferredWorkgroupSize = 64;

void createLayouts(const vk::Context& ctx, TraceKernel& kernel) {
  std::vector<VkDescriptorSetLayoutBinding> bindings =
      vk::storageBufferBindings(AMRSTREAM_TRACE_BINDING_COUNT, kernel.stages);
  bindings[AMRSTREAM_BINDING_TRACE_PARAMS].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  if (kernel.backend != Backend::Compute)
    bindings[AMRSTREAM_BINDING_TRACE_LOCATE].descriptorType =
        VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
  kernel.setLayout = vk::createDescriptorSetLayout(ctx, bindings);
  kernel.pipelineLayout = vk::createPipelineLayout(ctx, kernel.setLayout.get());
}

// The kernels' specialization constants: 0 the workgroup size (compute kernels), 1 whether
// samples test the previous region first (include/sampler.glsl), 2 the integrator
// (include/line_round.glsl), 3 deep positions (include/sampler.glsl), 4 dual values
// (include/sampler.glsl), 5 RK4's samples in a loop (include/line_round.glsl).
struct SpecializationValues {
  std::uint32_t workgroupSize;
  VkBool32 useRegionHint;
  std::int32_t integrator;
  VkBool32 deepPositions;
  VkBool32 dualValues;
  VkBool32 rk4SampleLoop;
};
constexpr std::array<VkSpecializationMapEntry, 6> kSpecializationEntries{
    {{0, offsetof(SpecializationValues, workgroupSize), sizeof(std::uint32_t)},
     {1, offsetof(SpecializationValues, useRegionHint), sizeof(VkBool32)},
     {2, offsetof(SpecializationValues, integrator), sizeof(std::int32_t)},
     {3, offsetof(SpecializationValues, deepPositions), sizeof(VkBool32)},
     {4, offsetof(SpecializationValues, dualValues), sizeof(VkBool32)},
     {5, offsetof(SpecializationValues, rk4SampleLoop), sizeof(VkBool32)}}};

VkBool32 rk4SampleLoop(const vk::Context& ctx, const KernelSettings& settings) {
  return settings.rk4SampleLoop.value_or(ctx.properties().deviceType ==
                                         VK_PHYSICAL_DEVICE_TYPE_CPU);
}

void createComputePipeline(const vk::Context& ctx, TraceKernel& kernel,
                           std::span<const std::uint32_t> code, const KernelSettings& settings) {
  kernel.workgroupSize =
      std::min(kPreferredWorkgroupSize, ctx.limits().maxComputeWorkGroupInvocations);
  const SpecializationValues values{kernel.workgroupSize,
                                    settings.useRegionHint,
                                    static_cast<std::int32_t>(settings.integrator),
                                    settings.deepPositions,
                                    settings.dualValues.value_or(false),
                                    rk4SampleLoop(ctx, settings)};
  const VkSpecializationInfo specialization{kSpecializationEntries.size(),
                                            kSpecializationEntries.data(), sizeof(values), &values};
  kernel.pipeline = vk::createComputePipeline(
      ctx, kernel.pipelineLayout.get(), code, &specialization,
      std::string("trace pipeline (") + std::string(backendName(kernel.backend)) + ")");
}

void createRayTracingPipeline(const vk::Context& ctx, TraceKernel& kernel,
                              std::span<const std::uint32_t> raygen,
                              const KernelSettings& settings) {
  const SpecializationValues values{0,
                                    settings.useRegionHint,
                                    static_cast<std::int32_t>(settings.integrator),
                                    settings.deepPositions,
                                    settings.dualValues.value_or(false),
                                    VK_TRUE};
  const VkSpecializationInfo specialization{kSpecializationEntries.size() - 1,
                                            &kSpecializationEntries[1], sizeof(values), &values};
  vk::RayTracingPipeline created = vk::createProceduralRayTracingPipeline(
      ctx, kernel.pipelineLayout.get(),
      {raygen, spirv(amrstream_spirv_locate_rmiss), spirv(amrstream_spirv_locate_rint),
       spirv(amrstream_spirv_locate_rchit)},
      &specialization, "trace pipeline (pipeline)");
  kernel.pipeline = std::move(created.pipeline);
  kernel.bindingTable = std::move(created.bindingTable);
}

}  // namespace

KernelSettings defaultKernelSettings(Backend) { return KernelSettings{}; }

std::uint32_t residentThreads(Backend backend) {
  return backend == Backend::Pipeline ? 1u << 16 : 1u << 17;
}

namespace {

// The entry point of `program` for `backend` (not Backend::Cpu).
std::span<const std::uint32_t> programCode(const vk::Context& ctx, Backend backend,
                                           KernelProgram program) {
  switch (program) {
    case KernelProgram::LocateProbe:
      return backend == Backend::Compute    ? spirv(amrstream_spirv_locate_probe_compute_comp)
             : backend == Backend::RayQuery ? spirv(amrstream_spirv_locate_probe_rayquery_comp)
                                            : spirv(amrstream_spirv_locate_probe_pipeline_rgen);
    case KernelProgram::GridProbe:
      return backend == Backend::Compute    ? spirv(amrstream_spirv_grid_probe_compute_comp)
             : backend == Backend::RayQuery ? spirv(amrstream_spirv_grid_probe_rayquery_comp)
                                            : spirv(amrstream_spirv_grid_probe_pipeline_rgen);
    case KernelProgram::Trace:
      break;
  }
  if (backend == Backend::Compute)
    return VolumeBuffers::addressesDualValues(ctx)
               ? spirv(amrstream_spirv_trace_compute_comp)
               : spirv(amrstream_spirv_trace_compute_compact_comp);
  return backend == Backend::RayQuery ? spirv(amrstream_spirv_trace_rayquery_comp)
                                      : spirv(amrstream_spirv_trace_pipeline_rgen);
}

}  // namespace

TraceKernel createTraceKernel(const vk::Context& ctx, Backend backend, KernelProgram program,
                              const KernelSettings& settings) {
  TraceKernel kernel;
  kernel.backend = backend;
  switch (backend) {
    case Backend::Compute:
    case Backend::RayQuery:
      kernel.bindPoint = VK_PIPELINE_BIND_POINT_COMPUTE;
      kernel.stages = VK_SHADER_STAGE_COMPUTE_BIT;
      createLayouts(ctx, kernel);
      createComputePipeline(ctx, kernel, programCode(ctx, backend, program), settings);
      break;
    case Backend::Pipeline:
      kernel.bindPoint = VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR;
      kernel.stages = VK_SHADER_STAGE_RAYGEN_BIT_KHR | VK_SHADER_STAGE_INTERSECTION_BIT_KHR |
                      VK_SHADER_STAGE_CLOSEST_HIT_BIT_KHR | VK_SHADER_STAGE_MISS_BIT_KHR;
      createLayouts(ctx, kernel);
      createRayTracingPipeline(ctx, kernel, programCode(ctx, backend, program), settings);
      break;
    case Backend::Cpu:
      throw std::invalid_argument("createTraceKernel: the cpu backend has no kernel");
  }
  return kernel;
}

}  // namespace amrstream::gpu
