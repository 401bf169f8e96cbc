#include "gpu_rounds.hpp"

#include <tbb/parallel_for.h>

#include <array>
#include <cstring>

#include "../../shaders/glsl/shared/round_params.h"
#include "flow/cell_point.hpp"
#include "flow/precise_position.hpp"
#include "util/stopwatch.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"

namespace amrstream::gpu {

namespace {

constexpr std::array<VkDescriptorPoolSize, 3> kPerSet{
    {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
     {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kCompactionBindingCount},
     {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1}}};

vk::DescriptorTarget storage(const vk::Buffer& buffer) {
  return {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffer.handle()};
}

std::uint32_t groups(std::size_t threads, std::uint32_t groupSize) {
  return static_cast<std::uint32_t>((threads + groupSize - 1) / groupSize);
}

// Copies `count` elements from a host-visible buffer into a new container, in parallel.
template <typename Container>
Container copyOut(const vk::Buffer& buffer, std::size_t count) {
  using T = typename Container::value_type;
  buffer.invalidateMapped();
  Container out(count);
  const T* source = reinterpret_cast<const T*>(buffer.mapped().data());
  constexpr std::size_t kGrain = std::size_t(1) << 16;
  tbb::parallel_for(std::size_t(0), (count + kGrain - 1) / kGrain, [&](std::size_t chunk) {
    const std::size_t first = chunk * kGrain, n = std::min(kGrain, count - first);
    std::memcpy(out.data() + first, source + first, n * sizeof(T));
  });
  return out;
}

void copyRange(VkCommandBuffer cmd, const vk::Buffer& from, const vk::Buffer& to,
               VkDeviceSize bytes) {
  if (bytes == 0) return;
  const VkBufferCopy region{0, 0, bytes};
  vkCmdCopyBuffer(cmd, from.handle(), to.handle(), 1, &region);
}

}  // namespace

GpuRounds::GpuRounds(const vk::Context& ctx, const TraceKernel& trace, const RoundKernels& kernels,
                     const VolumeBuffers& device, const flow::VectorVolume& volume,
                     std::span<const shared::LineState> lines, const flow::TraceOptions& options,
                     std::unique_ptr<RoundBuffers> buffers, bool timeKernels)
    : GpuRounds(ctx, trace, kernels, device, volume, lines, options, *buffers, timeKernels) {
  ownBuffers_ = std::move(buffers);
}

GpuRounds::GpuRounds(const vk::Context& ctx, const TraceKernel& trace, const RoundKernels& kernels,
                     const VolumeBuffers& device, const flow::VectorVolume& volume,
                     std::span<const shared::LineState> lines, const flow::TraceOptions& options,
                     RoundBuffers& buffers, bool timeKernels)
    : ctx_(&ctx), trace_(&trace), kernels_(&kernels), device_(&device), volume_(&volume),
      options_(options), params_(flow::makeTraceParams(volume, options)), buffers_(buffers),
      pool_(ctx, 5, kPerSet), live_(lines.size()), round_(ctx), copy_(ctx) {
  if (!buffers.fits(lines.size(), 2, volume.channelCount(), options.vorticity,
                   volume.deepPositions()))
    throw std::logic_error("GpuRounds: the round buffers do not fit the lines");
  buffers.setStates(ctx, lines);
  const RoundBuffers& b = buffers_;
  for (int parity = 0; parity < 2; ++parity) {
    traceSets_[parity] = pool_.allocate(trace.setLayout.get());
    const std::array<vk::DescriptorTarget, kTraceBindingCount> traceTargets{
        vk::DescriptorTarget{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, b.params.handle()},
        storage(device.bricks), storage(device.values), storage(device.regions),
        storage(device.regionBricks), storage(b.states), storage(b.roundStates),
        storage(b.lineRounds[parity]), storage(b.positions), storage(b.times),
        storage(b.vectors), storage(b.regionIds), device.locateTarget(),
        storage(device.vectorGradients)};
    vk::writeDescriptors(ctx, traceSets_[parity], traceTargets);

    compactionSets_[parity] = pool_.allocate(kernels.compactionSetLayout.get());
    const std::array<vk::DescriptorTarget, kCompactionBindingCount> compactionTargets{
        storage(b.lineRounds[parity]), storage(b.prefix), storage(b.blockSums),
        storage(b.summary), storage(b.roundStates), storage(b.states), storage(b.positions),
        storage(b.times), storage(b.vectors), storage(b.regionIds), storage(b.densePositions),
        storage(b.denseTimes), storage(b.denseVectors), storage(b.denseRegionIds)};
    vk::writeDescriptors(ctx, compactionSets_[parity], compactionTargets);
  }
  pointDataSet_ = pool_.allocate(kernels.pointDataSetLayout.get());
  const std::array<vk::DescriptorTarget, kPointDataBindingCount> pointDataTargets{
      storage(device.bricks), storage(device.values), storage(device.regions),
      storage(device.regionBricks), storage(device.channelValues), storage(b.summary),
      storage(b.densePositions), storage(b.denseRegionIds), storage(b.channels),
      storage(b.vorticity), storage(device.vectorGradients), storage(device.channelGradients)};
  vk::writeDescriptors(ctx, pointDataSet_, pointDataTargets);
  if (timeKernels) {
    traceTimer_.emplace(ctx);
    compactionTimer_.emplace(ctx);
  }
}

std::uint64_t GpuRounds::deviceBytes() const {
  const RoundBuffers& b = buffers_;
  std::uint64_t bytes = 0;
  for (const vk::Buffer* buffer :
       {&b.states, &b.roundStates, &b.lineRounds[0], &b.lineRounds[1], &b.prefix, &b.blockSums,
        &b.summary, &b.positions, &b.times, &b.vectors, &b.regionIds, &b.densePositions,
        &b.denseTimes, &b.denseVectors, &b.denseRegionIds, &b.channels, &b.vorticity})
    bytes += buffer->size();
  return bytes;
}

void GpuRounds::submitRound(std::uint32_t steps) {
  const std::size_t lines = live_;
  params_.lineCount = static_cast<std::uint32_t>(lines);
  params_.roundSteps = std::max(steps, 1u);
  params_.pointsPerLine = flow::pointsPerLine(options_, params_.roundSteps);
  if (std::uint64_t(lines) * params_.pointsPerLine > buffers_.pointCapacity)
    throw std::logic_error("GpuRounds: a round's output exceeds the batch's point slots");
  std::memcpy(buffers_.params.mapped().data(), &params_, sizeof(params_));
  roundLines_ = lines;
  const int parity = parity_;
  parity_ ^= 1;

  const bool pipeline = trace_->backend == Backend::Pipeline;
  const vk::Access traceAccess{pipeline ? VkPipelineStageFlags(VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR)
                                        : VkPipelineStageFlags(VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT),
                               VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
  const vk::Access compute{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                           VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
  const shared::CompactionParams compaction{params_.lineCount, params_.pointsPerLine};
  const shared::PointDataParams pointData{params_.cellsPerPhysical,
                                          static_cast<std::uint32_t>(volume_->channelCount()),
                                          options_.vorticity ? 1u : 0u,
                                          params_.linearInterpolant, params_.deepPositions};
  round_.submit([&](VkCommandBuffer cmd) {
    // The previous round's compaction wrote the states this round starts from. Its copy to the
    // host is left out of this dependency, so that this round's tracing may overlap it.
    vk::memoryBarrier(cmd, compute, {traceAccess.stages | compute.stages, traceAccess.access});
    if (traceTimer_) traceTimer_->start(cmd);
    vkCmdBindPipeline(cmd, trace_->bindPoint, trace_->pipeline.get());
    vkCmdBindDescriptorSets(cmd, trace_->bindPoint, trace_->pipelineLayout.get(), 0, 1,
                            &traceSets_[parity], 0, nullptr);
    if (pipeline) {
      const ShaderBindingTable& sbt = trace_->bindingTable;
      ctx_->functions().vkCmdTraceRaysKHR(cmd, &sbt.raygen, &sbt.miss, &sbt.hit, &sbt.callable,
                                          params_.lineCount, 1, 1);
    } else {
      vkCmdDispatch(cmd, groups(lines, trace_->workgroupSize), 1, 1);
    }
    if (traceTimer_) traceTimer_->stop(cmd);

    // The compaction overwrites the dense arrays the previous round's copy reads.
    vk::memoryBarrier(cmd, {traceAccess.stages | VK_PIPELINE_STAGE_TRANSFER_BIT,
                            VK_ACCESS_SHADER_WRITE_BIT},
                      compute);
    if (compactionTimer_) compactionTimer_->start(cmd);
    const VkPipelineLayout layout = kernels_->compactionLayout.get();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1,
                            &compactionSets_[parity], 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(compaction),
                       &compaction);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernels_->scanLines.get());
    vkCmdDispatch(cmd, groups(lines, AMRSTREAM_COMPACTION_GROUP), 1, 1);
    vk::memoryBarrier(cmd, compute, compute);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernels_->scanBlocks.get());
    vkCmdDispatch(cmd, 1, 1, 1);
    vk::memoryBarrier(cmd, compute,
                      {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                       compute.access | VK_ACCESS_INDIRECT_COMMAND_READ_BIT});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernels_->compact.get());
    vkCmdDispatch(cmd, groups(lines, AMRSTREAM_COMPACTION_GROUP), 1, 1);
    if (pointData.channelCount > 0 || pointData.computeVorticity != 0) {
      vk::memoryBarrier(cmd, compute, compute);
      const VkPipelineLayout pointLayout = kernels_->pointDataLayout.get();
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pointLayout, 0, 1,
                              &pointDataSet_, 0, nullptr);
      vkCmdPushConstants(cmd, pointLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pointData),
                         &pointData);
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernels_->pointData.get());
      vkCmdDispatchIndirect(cmd, buffers_.summary.handle(),
                            offsetof(shared::RoundSummary, pointGroups));
    }
    if (compactionTimer_) compactionTimer_->stop(cmd);

    vk::memoryBarrier(cmd, compute, vk::access::kTransferRead);
    copyRange(cmd, buffers_.summary, buffers_.summaryOut, sizeof(shared::RoundSummary));
    vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kHostRead);
  });
}

shared::RoundSummary GpuRounds::finishRound() {
  Stopwatch clock;
  round_.wait();
  times_.roundWaitSeconds += clock.seconds();
  buffers_.summaryOut.invalidateMapped();
  shared::RoundSummary summary;
  std::memcpy(&summary, buffers_.summaryOut.mapped().data(), sizeof(summary));
  const auto add = [](std::optional<double>& total, const std::optional<vk::GpuTimer>& timer) {
    if (!timer) return;
    const std::optional<double> seconds = timer->seconds();
    total = seconds ? std::optional(total.value_or(0.0) + *seconds) : std::nullopt;
  };
  add(times_.traceSeconds, traceTimer_);
  add(times_.compactionSeconds, compactionTimer_);
  ++times_.rounds;
  if (summary.points > std::uint64_t(roundLines_) * params_.pointsPerLine ||
      summary.liveLines > roundLines_)
    throw std::runtime_error("GpuRounds: the device reported more points or lines than it had");
  return summary;
}

void GpuRounds::submitCopy(const shared::RoundSummary& summary) {
  const int parity = parity_ ^ 1;  // the round submitted last
  const RoundBuffers& b = buffers_;
  const VkDeviceSize points = summary.points, channels = volume_->channelCount();
  copy_.submit([&](VkCommandBuffer cmd) {
    vk::memoryBarrier(cmd, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                      vk::access::kTransferRead);
    copyRange(cmd, b.lineRounds[parity], b.lineRoundsOut, roundLines_ * sizeof(shared::LineRound));
    copyRange(cmd, b.densePositions, b.positionsOut, points * sizeof(glm::vec3));
    copyRange(cmd, b.denseTimes, b.timesOut, points * sizeof(float));
    copyRange(cmd, b.denseVectors, b.vectorsOut, points * sizeof(glm::vec3));
    copyRange(cmd, b.channels, b.channelsOut, points * channels * sizeof(float));
    if (options_.vorticity) copyRange(cmd, b.vorticity, b.vorticityOut, points * sizeof(glm::vec3));
    if (b.withRegionIds)
      copyRange(cmd, b.denseRegionIds, b.regionIdsOut, points * sizeof(std::int32_t));
    vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kHostRead);
  });
}

flow::RoundBlock GpuRounds::finishCopy(const shared::RoundSummary& summary, std::size_t lines) {
  Stopwatch clock;
  copy_.wait();
  times_.copyWaitSeconds += clock.seconds();
  clock.restart();
  const RoundBuffers& b = buffers_;
  const std::size_t points = summary.points, channels = volume_->channelCount();
  flow::RoundBlock block;
  block.lines = copyOut<std::vector<shared::LineRound>>(b.lineRoundsOut, lines);
  block.times = copyOut<flow::Column<float>>(b.timesOut, points);
  block.vectors = copyOut<flow::Column<glm::vec3>>(b.vectorsOut, points);
  block.channels = copyOut<flow::Column<float>>(b.channelsOut, points * channels);
  if (options_.vorticity) block.vorticity = copyOut<flow::Column<glm::vec3>>(b.vorticityOut, points);
  // Kernels work in cell units, or offsets from regions' corners (line_state.h); convert in
  // double precision like the CPU path.
  b.positionsOut.invalidateMapped();
  const glm::vec3* cells = reinterpret_cast<const glm::vec3*>(b.positionsOut.mapped().data());
  block.positions.resize(points);
  const bricks::WorldTransform& transform = volume_->transform;
  if (b.withRegionIds) {  // deep positions: offsets from the regions' corners, kept precise
    b.regionIdsOut.invalidateMapped();
    const auto* ids = reinterpret_cast<const std::int32_t*>(b.regionIdsOut.mapped().data());
    const std::vector<shared::Region>& regions = volume_->regions.regions;
    block.positionsLow.resize(points);
    tbb::parallel_for(std::size_t(0), points, [&](std::size_t i) {
      const glm::ivec3 corner = ids[i] >= 0 && std::size_t(ids[i]) < regions.size()
                                    ? flow::regionCorner(regions[std::size_t(ids[i])].lower)
                                    : glm::ivec3(0);
      const flow::SplitPosition split = flow::splitPosition(
          transform.toPhysical(glm::dvec3(corner) + glm::dvec3(cells[i])));
      block.positions[i] = split.high;
      block.positionsLow[i] = split.low;
    });
  } else {
    tbb::parallel_for(std::size_t(0), points, [&](std::size_t i) {
      block.positions[i] = glm::vec3(transform.toPhysical(glm::dvec3(cells[i])));
    });
  }
  times_.unpackSeconds += clock.seconds();
  return block;
}

std::vector<shared::LineState> GpuRounds::liveStates() const {
  return buffers_.readStates(*ctx_, live_);
}

flow::RoundBlock GpuRounds::advance(std::uint32_t steps) {
  submitRound(steps);
  const shared::RoundSummary summary = finishRound();
  submitCopy(summary);
  live_ = summary.liveLines;
  return finishCopy(summary, roundLines_);
}

// The device traces round k+1 while the host waits for round k's copy and unpacks it. (Two host
// copies, so that round k's copy could overlap unpacking round k-1, measured slower on the H200:
// twice the pinned memory to make, and the copy competing with the unpacking for memory.)
void GpuRounds::runToEnd(const std::function<std::uint32_t(std::size_t live)>& stepsFor,
                         const std::function<void(flow::RoundBlock&&)>& consume) {
  if (live_ == 0) return;
  Stopwatch clock;
  submitRound(stepsFor(live_));
  times_.submitSeconds += clock.seconds();
  while (true) {
    const shared::RoundSummary summary = finishRound();
    const std::size_t lines = roundLines_;
    clock.restart();
    submitCopy(summary);
    live_ = summary.liveLines;
    if (live_ > 0) submitRound(stepsFor(live_));
    times_.submitSeconds += clock.seconds();
    flow::RoundBlock block = finishCopy(summary, lines);
    clock.restart();
    consume(std::move(block));
    times_.consumeSeconds += clock.seconds();
    if (live_ == 0) break;
  }
}

}  // namespace amrstream::gpu
