#include "plane_lic.hpp"

#include <cstring>
#include <stdexcept>

#include "flow/trace_options.hpp"
#include "lic_comp.h"
#include "util/stopwatch.hpp"
#include "vector_probe.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/descriptor_writes.hpp"
#include "vk/pipelines.hpp"

namespace amrstream::gpu {

namespace {

// The grid probe anchors its points (ProbeGrid::originAnchor); the reconstruction takes their
// integer offsets from the bricks exactly only with deep positions on (include/cell_point.glsl).
KernelSettings anchoredSamples() {
  KernelSettings settings;
  settings.deepPositions = true;
  return settings;
}

}  // namespace

PlaneLic::PlaneLic(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume)
    : ctx_(&ctx),
      volume_(&volume),
      device_(ctx, backend, volume, setup_),
      probe_(createTraceKernel(ctx, backend, KernelProgram::GridProbe, anchoredSamples())) {
  licSetLayout_ = vk::createDescriptorSetLayout(
      ctx, vk::storageBufferBindings(AMRSTREAM_LIC_BINDING_COUNT, VK_SHADER_STAGE_COMPUTE_BIT));
  licLayout_ = vk::createPipelineLayout(ctx, licSetLayout_.get(), sizeof(shared::LicParams),
                                        VK_SHADER_STAGE_COMPUTE_BIT);
  lic_ = vk::createComputePipeline(ctx, licLayout_.get(), vk::spirv(amrstream_spirv_lic_comp),
                                   nullptr, "lic");
  params_ = vk::Buffer::upload(ctx, sizeof(shared::TraceParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                               "slice probe params");
  grid_ = vk::Buffer::upload(ctx, sizeof(shared::ProbeGrid), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                             "slice probe grid");
  unused_ = vk::Buffer::deviceLocal(ctx, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "probe unused");
}

void PlaneLic::reserve(std::size_t pixels) {
  if (pixels <= capacity_) return;
  const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  vectors_ = vk::Buffer::deviceLocal(*ctx_, pixels * sizeof(glm::vec3), usage, "slice vectors");
  intensity_ = vk::Buffer::readback(*ctx_, pixels * sizeof(float), usage, "lic intensity");
  const std::array<VkDescriptorPoolSize, 3> sizes{
      {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
       {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, AMRSTREAM_TRACE_BINDING_COUNT},
       {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1}}};
  pool_ = std::make_unique<vk::DescriptorPool>(*ctx_, 2, sizes);
  probeSet_ = pool_->allocate(probe_.setLayout.get());
  licSet_ = pool_->allocate(licSetLayout_.get());
  writeProbeSet(*ctx_, probeSet_, device_, params_, grid_, vectors_, unused_, unused_);
  vk::DescriptorWrites("lic", AMRSTREAM_LIC_BINDING_COUNT)
      .set(AMRSTREAM_BINDING_LIC_VECTORS, vectors_)
      .set(AMRSTREAM_BINDING_LIC_INTENSITY, intensity_)
      .write(*ctx_, licSet_);
  capacity_ = pixels;
}

std::vector<float> PlaneLic::convolve(const shared::ProbeGrid& grid,
                                      const shared::LicParams& params) {
  if (params.width != grid.width || params.height != grid.height)
    throw std::invalid_argument("PlaneLic::convolve: the grid's and the LIC's sizes differ");
  const std::size_t pixels = std::size_t(grid.width) * grid.height;
  if (pixels == 0) return {};
  reserve(pixels);
  Stopwatch clock;
  flow::TraceOptions options;
  options.keepHistory = false;
  const shared::TraceParams trace = flow::makeTraceParams(*volume_, options);
  std::memcpy(params_.mapped().data(), &trace, sizeof(trace));
  std::memcpy(grid_.mapped().data(), &grid, sizeof(grid));
  const auto groups = [](std::uint32_t n, std::uint32_t size) { return (n + size - 1) / size; };
  vk::submitAndWait(*ctx_, [&](VkCommandBuffer cmd) {
    vk::memoryBarrier(cmd, vk::access::kHostWrite, vk::access::kAny);
    vkCmdBindPipeline(cmd, probe_.bindPoint, probe_.pipeline.get());
    vkCmdBindDescriptorSets(cmd, probe_.bindPoint, probe_.pipelineLayout.get(), 0, 1, &probeSet_, 0,
                            nullptr);
    if (probe_.backend == Backend::Pipeline) {
      const ShaderBindingTable& sbt = probe_.bindingTable;
      ctx_->functions().vkCmdTraceRaysKHR(cmd, &sbt.raygen, &sbt.miss, &sbt.hit, &sbt.callable,
                                          grid.width, grid.height, 1);
    } else {
      vkCmdDispatch(cmd, groups(grid.width, probe_.workgroupSize), grid.height, 1);
    }
    vk::memoryBarrier(cmd, vk::access::kAnyWrite, vk::access::kComputeShaderRead);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, lic_.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, licLayout_.get(), 0, 1, &licSet_,
                            0, nullptr);
    vkCmdPushConstants(cmd, licLayout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(params),
                       &params);
    vkCmdDispatch(cmd, groups(grid.width, AMRSTREAM_LIC_GROUP),
                  groups(grid.height, AMRSTREAM_LIC_GROUP), 1);
    vk::memoryBarrier(cmd, vk::access::kComputeShaderWrite, vk::access::kHostRead);
  });
  times_.deviceSeconds += clock.seconds();
  clock.restart();
  intensity_.invalidateMapped();
  std::vector<float> intensity(pixels);
  std::memcpy(intensity.data(), intensity_.mapped().data(), pixels * sizeof(float));
  times_.readSeconds += clock.seconds();
  return intensity;
}

}  // namespace amrstream::gpu
