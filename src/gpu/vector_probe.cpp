#include "vector_probe.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "../../shaders/glsl/shared/line_state.h"
#include "flow/trace_options.hpp"
#include "util/stopwatch.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/descriptor_writes.hpp"

namespace amrstream::gpu {

namespace {

// Points per dispatch: within every backend's dispatch limits, and buffers of a few tens of MB.
constexpr std::size_t kPointsPerDispatch = std::size_t(1) << 20;

}  // namespace

void writeProbeSet(const vk::Context& ctx, VkDescriptorSet set, const VolumeBuffers& device,
                   const vk::Buffer& params, const vk::Buffer& points, const vk::Buffer& vectors,
                   const vk::Buffer& regions, const vk::Buffer& unused) {
  vk::DescriptorWrites("probe", AMRSTREAM_TRACE_BINDING_COUNT)
      .set(AMRSTREAM_BINDING_TRACE_PARAMS, vk::uniformTarget(params))
      .set(AMRSTREAM_BINDING_TRACE_BRICKS, device.bricks)
      .set(AMRSTREAM_BINDING_TRACE_VALUES, device.values)
      .set(AMRSTREAM_BINDING_TRACE_REGIONS, device.regions)
      .set(AMRSTREAM_BINDING_TRACE_REGION_BRICKS, device.regionBricks)
      .set(AMRSTREAM_BINDING_TRACE_PROBE_POINTS, points)
      .set(AMRSTREAM_BINDING_TRACE_STATES_OUT, unused)
      .set(AMRSTREAM_BINDING_TRACE_LINE_ROUNDS, unused)
      .set(AMRSTREAM_BINDING_TRACE_POSITIONS, unused)
      .set(AMRSTREAM_BINDING_TRACE_TIMES, unused)
      .set(AMRSTREAM_BINDING_TRACE_VECTORS, vectors)
      .set(AMRSTREAM_BINDING_TRACE_REGION_IDS, regions)
      .set(AMRSTREAM_BINDING_TRACE_LOCATE, device.locateTarget())
      .set(AMRSTREAM_BINDING_TRACE_LINEAR_CELLS, device.vectorGradients)
      .write(ctx, set);
}

shared::TraceParams probeParams(const flow::VectorVolume& volume, std::size_t points) {
  flow::TraceOptions options;
  options.keepHistory = false;
  shared::TraceParams params = flow::makeTraceParams(volume, options);
  params.lineCount = std::uint32_t(points);
  return params;
}

void recordProbe(const vk::Context& ctx, const TraceKernel& kernel, VkCommandBuffer cmd,
                 VkDescriptorSet set, std::size_t points) {
  vkCmdBindPipeline(cmd, kernel.bindPoint, kernel.pipeline.get());
  vkCmdBindDescriptorSets(cmd, kernel.bindPoint, kernel.pipelineLayout.get(), 0, 1, &set, 0,
                          nullptr);
  if (kernel.backend == Backend::Pipeline) {
    const ShaderBindingTable& sbt = kernel.bindingTable;
    ctx.functions().vkCmdTraceRaysKHR(cmd, &sbt.raygen, &sbt.miss, &sbt.hit, &sbt.callable,
                                      std::uint32_t(points), 1, 1);
  } else {
    vkCmdDispatch(cmd, std::uint32_t((points + kernel.workgroupSize - 1) / kernel.workgroupSize), 1,
                  1);
  }
}

VectorProbe::VectorProbe(const vk::Context& ctx, const TraceKernel& kernel,
                         const flow::VectorVolume& volume)
    : ctx_(&ctx), volume_(&volume), kernel_(&kernel) {
  owned_.emplace(ctx, kernel.backend, volume, setup_);
  device_ = &*owned_;
  makeFixedBuffers();
}

VectorProbe::VectorProbe(const vk::Context& ctx, const TraceKernel& kernel,
                         const flow::VectorVolume& volume, const VolumeBuffers& device)
    : ctx_(&ctx), volume_(&volume), device_(&device), kernel_(&kernel) {
  makeFixedBuffers();
}

void VectorProbe::makeFixedBuffers() {
  const vk::Context& ctx = *ctx_;
  params_ = vk::Buffer::upload(ctx, sizeof(shared::TraceParams), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                               "probe params");
  unused_ = vk::Buffer::deviceLocal(ctx, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "probe unused");
}

void VectorProbe::reserve(std::size_t points) {
  if (points <= capacity_) return;
  const VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  points_ = vk::Buffer::upload(*ctx_, points * sizeof(glm::vec3), usage, "probe points");
  vectors_ = vk::Buffer::readback(*ctx_, points * sizeof(glm::vec3), usage, "probe vectors");
  regions_ = vk::Buffer::readback(*ctx_, points * sizeof(std::int32_t),
                                  usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, "probe regions");
  clearHints_ = true;
  const std::array<VkDescriptorPoolSize, 3> sizes{
      {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
       {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, AMRSTREAM_TRACE_BINDING_COUNT},
       {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1}}};
  pool_ = std::make_unique<vk::DescriptorPool>(*ctx_, 1, sizes);
  set_ = pool_->allocate(kernel_->setLayout.get());
  writeSet();
  capacity_ = points;
}

void VectorProbe::writeSet() {
  writeProbeSet(*ctx_, set_, *device_, params_, points_, vectors_, regions_, unused_);
}

void VectorProbe::sample(std::span<const glm::vec3> cellPoints, std::span<flow::VectorSample> out) {
  reserve(std::min(kPointsPerDispatch, cellPoints.size()));
  for (std::size_t first = 0; first < cellPoints.size(); first += kPointsPerDispatch) {
    const std::size_t n = std::min(kPointsPerDispatch, cellPoints.size() - first);
    Stopwatch clock;
    auto* points = reinterpret_cast<glm::vec3*>(points_.mapped().data());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16384), [&](const auto& range) {
      std::memcpy(points + range.begin(), cellPoints.data() + first + range.begin(),
                  (range.end() - range.begin()) * sizeof(glm::vec3));
    });
    const shared::TraceParams params = probeParams(*volume_, n);
    std::memcpy(params_.mapped().data(), &params, sizeof(params));
    times_.writeSeconds += clock.seconds();
    clock.restart();
    vk::submitAndWait(*ctx_, [&](VkCommandBuffer cmd) {
      vk::memoryBarrier(cmd, vk::access::kHostWrite, vk::access::kAny);
      if (clearHints_) {  // no region hints yet (locate_probe.glsl): later calls start from the
                          // regions found last
        vkCmdFillBuffer(cmd, regions_.handle(), 0, VK_WHOLE_SIZE, ~0u);
        vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kAny);
        clearHints_ = false;
      }
      recordProbe(*ctx_, *kernel_, cmd, set_, n);
      vk::memoryBarrier(cmd, vk::access::kAnyWrite, vk::access::kHostRead);
    });
    times_.deviceSeconds += clock.seconds();
    clock.restart();
    vectors_.invalidateMapped();
    regions_.invalidateMapped();
    const auto* vectors = reinterpret_cast<const glm::vec3*>(vectors_.mapped().data());
    const auto* regions = reinterpret_cast<const std::int32_t*>(regions_.mapped().data());
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      flow::VectorSample& s = out[first + i];
      s = {};
      s.region = regions[i];
      s.located = regions[i] >= 0;
      if (!s.located) return;
      s.cellWidth = volume_->regions.regions[std::size_t(regions[i])].finestCellWidth;
      s.value = vectors[i];
      s.valid = !glm::any(glm::isnan(s.value)) && !glm::any(glm::isinf(s.value));
      if (!s.valid) s.value = glm::vec3(0.0f);
    });
    times_.readSeconds += clock.seconds();
    ++times_.calls;
  }
}

}  // namespace amrstream::gpu
