#include "gpu_rounds.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "../../shaders/glsl/shared/round_bindings.h"
#include "../../shaders/glsl/shared/round_params.h"
#include "../../shaders/glsl/shared/trace_bindings.h"
#include "point_positions.hpp"
#include "staged_layout.hpp"
#include "util/stopwatch.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/descriptor_writes.hpp"

namespace amrstream::gpu {

namespace {

constexpr std::uint32_t kMostLaneShift = 5;  // a line alone in a subgroup of 32

constexpr std::array<VkDescriptorPoolSize, 3> kPerSet{
    {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
     {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
      std::max({AMRSTREAM_TRACE_BINDING_COUNT, AMRSTREAM_COMPACTION_BINDING_COUNT,
                AMRSTREAM_POINT_DATA_BINDING_COUNT})},
     {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1}}};

std::uint32_t groups(std::size_t threads, std::uint32_t groupSize) {
  return static_cast<std::uint32_t>((threads + groupSize - 1) / groupSize);
}

void copyRange(VkCommandBuffer cmd, const vk::Buffer& from, VkDeviceSize fromOffset,
               const vk::Buffer& to, VkDeviceSize toOffset, VkDeviceSize bytes) {
  if (bytes == 0) return;
  const VkBufferCopy region{fromOffset, toOffset, bytes};
  vkCmdCopyBuffer(cmd, from.handle(), to.handle(), 1, &region);
}

// Unpacks the `count` points a staging slot holds (laid out as `layout`) into `block` from point
// `first` on. Kernels work in cell units, or offsets from regions' corners (line_state.h);
// positions are converted to physical coordinates in double precision, like the CPU path's.
void unpackPiece(const StagedLayout& layout, const vk::Buffer& slot, std::size_t first,
                 std::size_t count, const flow::VectorVolume& volume, flow::RoundBlock& block) {
  const std::size_t channels = volume.channelCount();
  const std::span<const std::byte> bytes = slot.mapped();
  const auto* cells = layout.in<glm::vec3>(bytes, StagedLayout::kCells, count);
  const auto* times = layout.in<float>(bytes, StagedLayout::kTimes, count);
  const auto* vectors = layout.in<glm::vec3>(bytes, StagedLayout::kVectors, count);
  const auto* values = layout.in<float>(bytes, StagedLayout::kChannels, count);
  const bool withVorticity = layout.vorticity() < layout.arrays().size();
  const bool withIds = layout.regionIds() < layout.arrays().size();
  const auto* vorticity =
      withVorticity ? layout.in<glm::vec3>(bytes, layout.vorticity(), count) : nullptr;
  const auto* ids = withIds ? layout.in<std::int32_t>(bytes, layout.regionIds(), count) : nullptr;
  constexpr std::size_t kGrain = std::size_t(1) << 14;
  tbb::parallel_for(std::size_t(0), (count + kGrain - 1) / kGrain, [&](std::size_t chunk) {
    const std::size_t from = chunk * kGrain, n = std::min(kGrain, count - from);
    const std::size_t to = first + from;
    std::memcpy(block.times.data() + to, times + from, n * sizeof(float));
    std::memcpy(block.vectors.data() + to, vectors + from, n * sizeof(glm::vec3));
    if (channels > 0)
      std::memcpy(block.channels.data() + to * channels, values + from * channels,
                  n * channels * sizeof(float));
    if (vorticity)
      std::memcpy(block.vorticity.data() + to, vorticity + from, n * sizeof(glm::vec3));
    toPhysicalPositions(volume, cells + from, ids ? ids + from : nullptr, n,
                        block.positions.data() + to,
                        ids ? block.positionsLow.data() + to : nullptr);
  });
}

// The tracing round's bindings; `parity` picks the line reports the round writes. The kernel
// reads dual cells with their own region brick records where the volume has them.
void writeTraceSet(const vk::Context& ctx, VkDescriptorSet set, const VolumeBuffers& device,
                   const RoundBuffers& b, int parity) {
  const bool dual = device.dualValues.size() > 0;
  vk::DescriptorWrites("trace", AMRSTREAM_TRACE_BINDING_COUNT)
      .set(AMRSTREAM_BINDING_TRACE_PARAMS, vk::uniformTarget(b.params))
      .set(AMRSTREAM_BINDING_TRACE_BRICKS, device.bricks)
      .set(AMRSTREAM_BINDING_TRACE_VALUES, device.values)
      .set(AMRSTREAM_BINDING_TRACE_REGIONS, device.regions)
      .set(AMRSTREAM_BINDING_TRACE_REGION_BRICKS,
           dual ? device.dualRegionBricks : device.regionBricks)
      .set(AMRSTREAM_BINDING_TRACE_STATES_IN, b.states)
      .set(AMRSTREAM_BINDING_TRACE_STATES_OUT, b.roundStates)
      .set(AMRSTREAM_BINDING_TRACE_LINE_ROUNDS, b.lineRounds[parity])
      .set(AMRSTREAM_BINDING_TRACE_POSITIONS, b.positions)
      .set(AMRSTREAM_BINDING_TRACE_TIMES, b.times)
      .set(AMRSTREAM_BINDING_TRACE_VECTORS, b.vectors)
      .set(AMRSTREAM_BINDING_TRACE_REGION_IDS, b.regionIds)
      .set(AMRSTREAM_BINDING_TRACE_LOCATE, device.locateTarget())
      .set(AMRSTREAM_BINDING_TRACE_LINEAR_CELLS, device.vectorGradients)
      .write(ctx, set);
}

void writeCompactionSet(const vk::Context& ctx, VkDescriptorSet set, const RoundBuffers& b,
                        int parity) {
  vk::DescriptorWrites("compaction", AMRSTREAM_COMPACTION_BINDING_COUNT)
      .set(AMRSTREAM_BINDING_COMPACTION_LINE_ROUNDS, b.lineRounds[parity])
      .set(AMRSTREAM_BINDING_COMPACTION_PREFIX, b.prefix)
      .set(AMRSTREAM_BINDING_COMPACTION_BLOCK_SUMS, b.blockSums)
      .set(AMRSTREAM_BINDING_COMPACTION_SUMMARY, b.summary)
      .set(AMRSTREAM_BINDING_COMPACTION_STATES, b.roundStates)
      .set(AMRSTREAM_BINDING_COMPACTION_NEXT_STATES, b.states)
      .set(AMRSTREAM_BINDING_COMPACTION_POSITIONS, b.positions)
      .set(AMRSTREAM_BINDING_COMPACTION_TIMES, b.times)
      .set(AMRSTREAM_BINDING_COMPACTION_VECTORS, b.vectors)
      .set(AMRSTREAM_BINDING_COMPACTION_REGION_IDS, b.regionIds)
      .set(AMRSTREAM_BINDING_COMPACTION_DENSE_POSITIONS, b.densePositions)
      .set(AMRSTREAM_BINDING_COMPACTION_DENSE_TIMES, b.denseTimes)
      .set(AMRSTREAM_BINDING_COMPACTION_DENSE_VECTORS, b.denseVectors)
      .set(AMRSTREAM_BINDING_COMPACTION_DENSE_REGION_IDS, b.denseRegionIds)
      .write(ctx, set);
}

}  // namespace

GpuRounds::GpuRounds(const vk::Context& ctx, const TraceKernel& trace, const RoundKernels& kernels,
                     const VolumeBuffers& device, const flow::VectorVolume& volume,
                     std::span<const shared::LineState> lines, const flow::TraceOptions& options,
                     std::unique_ptr<RoundBuffers> buffers, StagingRing& staging, bool timeKernels)
    : GpuRounds(ctx, trace, kernels, device, volume, lines, options, *buffers, staging,
                timeKernels) {
  ownBuffers_ = std::move(buffers);
}

GpuRounds::GpuRounds(const vk::Context& ctx, const TraceKernel& trace, const RoundKernels& kernels,
                     const VolumeBuffers& device, const flow::VectorVolume& volume,
                     std::span<const shared::LineState> lines, const flow::TraceOptions& options,
                     RoundBuffers& buffers, StagingRing& staging, bool timeKernels)
    : ctx_(&ctx),
      trace_(&trace),
      kernels_(&kernels),
      device_(&device),
      volume_(&volume),
      options_(options),
      params_(flow::makeTraceParams(volume, options)),
      buffers_(buffers),
      staging_(staging),
      pool_(ctx, 5, kPerSet),
      live_(lines.size()),
      round_(ctx) {
  if (!buffers.fits(lines.size(), 2, volume.channelCount(), options.vorticity,
                    volume.deepPositions()))
    throw std::logic_error("GpuRounds: the round buffers do not fit the lines");
  buffers.setStates(ctx, lines);
  // The kernel reads dual cells through their address where the volume has them (GpuTracer
  // sets both alike).
  params_.dualValuesAddress = device.dualValuesAddress();
  for (int parity = 0; parity < 2; ++parity) {
    traceSets_[parity] = pool_.allocate(trace.setLayout.get());
    writeTraceSet(ctx, traceSets_[parity], device, buffers_, parity);
    compactionSets_[parity] = pool_.allocate(kernels.compactionSetLayout.get());
    writeCompactionSet(ctx, compactionSets_[parity], buffers_, parity);
  }
  pointDataSet_ = pool_.allocate(kernels.pointDataSetLayout.get());
  writePointDataSet(ctx, pointDataSet_, device,
                    {buffers_.summary, buffers_.densePositions, buffers_.denseRegionIds,
                     buffers_.channels, buffers_.vorticity});
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

void GpuRounds::compileByDispatch() {
  if (live_ != 0) throw std::logic_error("GpuRounds: kernels are compiled on no lines");
  submitRound(1, true);
  round_.wait();
  parity_ ^= 1;
}

void GpuRounds::submitRound(std::uint32_t steps, bool everyKernel) {
  const std::size_t lines = live_;
  params_.lineCount = static_cast<std::uint32_t>(lines);
  params_.laneShift = 0;
  while (params_.laneShift < kMostLaneShift &&
         (std::uint64_t(lines) << (params_.laneShift + 1)) <= spreadThreads_)
    ++params_.laneShift;
  const std::size_t invocations = lines << params_.laneShift;
  times_.mostLanesPerLine = std::max(times_.mostLanesPerLine, 1u << params_.laneShift);
  params_.roundSteps = std::max(steps, 1u);
  params_.pointsPerLine = flow::pointsPerLine(options_, params_.roundSteps);
  if (std::uint64_t(lines) * params_.pointsPerLine > buffers_.pointCapacity)
    throw std::logic_error("GpuRounds: a round's output exceeds the batch's point slots");
  std::memcpy(buffers_.params.mapped().data(), &params_, sizeof(params_));
  roundLines_ = lines;
  const int parity = parity_;
  parity_ ^= 1;

  const bool pipeline = trace_->backend == Backend::Pipeline;
  const vk::Access traceAccess{
      pipeline ? VkPipelineStageFlags(VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR)
               : VkPipelineStageFlags(VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT),
      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
  const vk::Access compute{VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                           VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
  const shared::CompactionParams compaction{params_.lineCount, params_.pointsPerLine};
  const shared::PointDataParams pointData{
      params_.cellsPerPhysical, static_cast<std::uint32_t>(volume_->channelCount()),
      options_.vorticity ? 1u : 0u, params_.linearInterpolant, params_.deepPositions};
  const auto groupsOf = [everyKernel](std::size_t threads, std::uint32_t groupSize) {
    return std::max(groups(threads, groupSize), everyKernel ? 1u : 0u);
  };
  const auto rays = static_cast<std::uint32_t>(std::max<std::size_t>(invocations, everyKernel));
  const bool timed = !everyKernel;
  round_.submit([&](VkCommandBuffer cmd) {
    // The previous round's compaction wrote the states this round starts from. Its copy to the
    // host is left out of this dependency, so that this round's tracing may overlap it.
    vk::memoryBarrier(cmd, compute, {traceAccess.stages | compute.stages, traceAccess.access});
    if (traceTimer_ && timed) traceTimer_->start(cmd);
    vkCmdBindPipeline(cmd, trace_->bindPoint, trace_->pipeline.get());
    vkCmdBindDescriptorSets(cmd, trace_->bindPoint, trace_->pipelineLayout.get(), 0, 1,
                            &traceSets_[parity], 0, nullptr);
    if (pipeline) {
      const ShaderBindingTable& sbt = trace_->bindingTable;
      ctx_->functions().vkCmdTraceRaysKHR(cmd, &sbt.raygen, &sbt.miss, &sbt.hit, &sbt.callable,
                                          rays, 1, 1);
    } else {
      vkCmdDispatch(cmd, groupsOf(invocations, trace_->workgroupSize), 1, 1);
    }
    if (traceTimer_ && timed) traceTimer_->stop(cmd);

    // The compaction overwrites the dense arrays the previous round's copy reads.
    vk::memoryBarrier(
        cmd, {traceAccess.stages | VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
        compute);
    if (compactionTimer_ && timed) compactionTimer_->start(cmd);
    const VkPipelineLayout layout = kernels_->compactionLayout.get();
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1,
                            &compactionSets_[parity], 0, nullptr);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(compaction),
                       &compaction);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernels_->scanLines.get());
    vkCmdDispatch(cmd, groupsOf(lines, AMRSTREAM_COMPACTION_GROUP), 1, 1);
    vk::memoryBarrier(cmd, compute, compute);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernels_->scanBlocks.get());
    vkCmdDispatch(cmd, 1, 1, 1);
    vk::memoryBarrier(cmd, compute,
                      {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                       compute.access | VK_ACCESS_INDIRECT_COMMAND_READ_BIT});
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernels_->compact.get());
    vkCmdDispatch(cmd, groupsOf(lines, AMRSTREAM_COMPACTION_GROUP), 1, 1);
    if (pointData.channelCount > 0 || pointData.computeVorticity != 0) {
      vk::memoryBarrier(cmd, compute, compute);
      const VkPipelineLayout pointLayout = kernels_->pointDataLayout.get();
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pointLayout, 0, 1,
                              &pointDataSet_, 0, nullptr);
      vkCmdPushConstants(cmd, pointLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(pointData),
                         &pointData);
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernels_->pointData.get());
      if (everyKernel)
        vkCmdDispatch(cmd, 1, 1, 1);  // the compaction counted no points: the kernel returns
      else
        vkCmdDispatchIndirect(cmd, buffers_.summary.handle(),
                              offsetof(shared::RoundSummary, pointGroups));
    }
    if (compactionTimer_ && timed) compactionTimer_->stop(cmd);

    vk::memoryBarrier(cmd, compute, vk::access::kTransferRead);
    copyRange(cmd, buffers_.summary, 0, buffers_.summaryOut, 0, sizeof(shared::RoundSummary));
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

flow::RoundBlock GpuRounds::readRound(const shared::RoundSummary& summary, std::size_t lines,
                                      const std::function<void()>& afterLastCopy) {
  Stopwatch clock;
  const RoundBuffers& b = buffers_;
  const vk::Buffer& reports = b.lineRounds[parity_ ^ 1];  // the round submitted last
  const std::size_t points = summary.points, channels = volume_->channelCount();
  const StagedLayout layout(b, channels, options_.vorticity);
  const std::size_t perPiece = staging_.slotBytes() / layout.bytesPerPoint();
  if (perPiece == 0) throw std::logic_error("GpuRounds: a staging slot holds no whole point");
  const std::size_t pieces = std::max<std::size_t>(1, (points + perPiece - 1) / perPiece);
  const std::size_t slots = staging_.slots();
  const auto piecePoints = [&](std::size_t piece) {
    const std::size_t first = piece * perPiece;
    return std::pair(first, std::min(perPiece, points - std::min(points, first)));
  };
  const auto submitPiece = [&](std::size_t piece) {
    const auto [first, count] = piecePoints(piece);
    const vk::Buffer& slot = staging_.buffer(piece % slots);
    staging_.submission(piece % slots).submit([&](VkCommandBuffer cmd) {
      vk::memoryBarrier(cmd, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                        vk::access::kTransferRead);
      if (piece == 0)
        copyRange(cmd, reports, 0, b.lineRoundsOut, 0, lines * sizeof(shared::LineRound));
      for (const StagedArray& array : layout.arrays())
        copyRange(cmd, *array.source, first * array.bytesPerPoint, slot, array.offset * count,
                  count * array.bytesPerPoint);
      vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kHostRead);
    });
    if (piece + 1 == pieces && afterLastCopy) afterLastCopy();
  };
  for (std::size_t piece = 0; piece < std::min(pieces, slots); ++piece) submitPiece(piece);

  flow::RoundBlock block;
  block.positions.resize(points);
  block.times.resize(points);
  block.vectors.resize(points);
  block.channels.resize(points * channels);
  if (options_.vorticity) block.vorticity.resize(points);
  if (b.withRegionIds) block.positionsLow.resize(points);
  times_.submitSeconds += clock.seconds();

  for (std::size_t piece = 0; piece < pieces; ++piece) {
    clock.restart();
    vk::Submission& copy = staging_.submission(piece % slots);
    copy.wait();
    times_.copyWaitSeconds += clock.seconds();
    clock.restart();
    const vk::Buffer& slot = staging_.buffer(piece % slots);
    slot.invalidateMapped();
    if (piece == 0) {
      b.lineRoundsOut.invalidateMapped();
      const auto* reported =
          reinterpret_cast<const shared::LineRound*>(b.lineRoundsOut.mapped().data());
      block.lines.assign(reported, reported + lines);
    }
    const auto [first, count] = piecePoints(piece);
    unpackPiece(layout, slot, first, count, *volume_, block);
    times_.unpackSeconds += clock.seconds();
    clock.restart();
    if (piece + slots < pieces) submitPiece(piece + slots);
    times_.submitSeconds += clock.seconds();
  }
  return block;
}

std::vector<shared::LineState> GpuRounds::liveStates() const {
  return buffers_.readStates(*ctx_, live_);
}

flow::RoundBlock GpuRounds::advance(std::uint32_t steps) {
  submitRound(steps);
  const shared::RoundSummary summary = finishRound();
  live_ = summary.liveLines;
  return readRound(summary, roundLines_, {});
}

KeptRound GpuRounds::roomForRound(std::uint64_t pointsLeft) const {
  const StagedLayout layout(buffers_, volume_->channelCount(), options_.vorticity);
  const std::uint64_t most =
      std::min(std::uint64_t(roundLines_) * params_.pointsPerLine, pointsLeft);
  KeptRound kept;
  for (const StagedArray& array : layout.arrays())
    kept.arrays.push_back(vk::Buffer::deviceLocal(
        *ctx_, most * array.bytesPerPoint,
        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, "kept points"));
  return kept;
}

void GpuRounds::keepRound(const shared::RoundSummary& summary, std::size_t lines,
                          const std::function<void()>& afterCopy, KeptRound& kept,
                          std::vector<shared::LineRound>& reports) {
  Stopwatch clock;
  const RoundBuffers& b = buffers_;
  const vk::Buffer& reported = b.lineRounds[parity_ ^ 1];  // the round submitted last
  const StagedLayout layout(b, volume_->channelCount(), options_.vorticity);
  kept.points = summary.points;
  for (std::size_t i = 0; i < layout.arrays().size(); ++i)
    if (kept.arrays[i].size() < summary.points * layout.arrays()[i].bytesPerPoint)
      throw std::logic_error("GpuRounds: a round emitted more points than it had room for");
  if (!keepCopy_) keepCopy_.emplace(*ctx_);
  keepCopy_->submit([&](VkCommandBuffer cmd) {
    vk::memoryBarrier(cmd, {VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT},
                      vk::access::kTransferRead);
    copyRange(cmd, reported, 0, b.lineRoundsOut, 0, lines * sizeof(shared::LineRound));
    for (std::size_t i = 0; i < layout.arrays().size(); ++i)
      copyRange(cmd, *layout.arrays()[i].source, 0, kept.arrays[i], 0,
                summary.points * layout.arrays()[i].bytesPerPoint);
    vk::memoryBarrier(cmd, vk::access::kTransferWrite, vk::access::kHostRead);
  });
  afterCopy();
  times_.submitSeconds += clock.seconds();
  clock.restart();
  keepCopy_->wait();
  times_.copyWaitSeconds += clock.seconds();
  b.lineRoundsOut.invalidateMapped();
  const auto* reportedLines =
      reinterpret_cast<const shared::LineRound*>(b.lineRoundsOut.mapped().data());
  reports.assign(reportedLines, reportedLines + lines);
}

// The device traces round k + 1 while the host unpacks the last pieces of round k.
void GpuRounds::runRounds(
    const std::function<std::uint32_t(std::size_t live)>& stepsFor,
    const std::function<void()>& whileTracing,
    const std::function<void(const shared::RoundSummary&, const std::function<void()>&)>& take,
    std::size_t stopAt) {
  if (live_ == 0) return;
  Stopwatch clock;
  submitRound(stepsFor(live_));
  times_.submitSeconds += clock.seconds();
  while (true) {
    if (whileTracing) whileTracing();
    const shared::RoundSummary summary = finishRound();
    live_ = summary.liveLines;
    take(summary, [&] {
      if (live_ > stopAt) submitRound(stepsFor(live_));
    });
    if (live_ <= stopAt) break;
  }
}

void GpuRounds::runToEnd(const std::function<std::uint32_t(std::size_t live)>& stepsFor,
                         const std::function<void(flow::RoundBlock&&)>& consume,
                         std::size_t stopAt) {
  runRounds(
      stepsFor, {},
      [&](const shared::RoundSummary& summary, const std::function<void()>& submitNext) {
        flow::RoundBlock block = readRound(summary, roundLines_, submitNext);
        Stopwatch clock;
        consume(std::move(block));
        times_.consumeSeconds += clock.seconds();
      },
      stopAt);
}

// Each round's buffers are made while the device traces it.
void GpuRounds::runToEndOnDevice(
    const std::function<std::uint32_t(std::size_t live)>& stepsFor,
    const std::function<void(std::vector<shared::LineRound>&&, KeptRound&&)>& keep) {
  // No line holds more than maxSteps + 1 points: the batch's points still to come are bounded.
  std::uint64_t pointsLeft =
      std::uint64_t(live_) * (options_.keepHistory ? std::uint64_t(options_.maxSteps) + 1 : 1);
  KeptRound room;
  runRounds(
      stepsFor,
      [&] {
        Stopwatch clock;
        room = roomForRound(pointsLeft);
        times_.submitSeconds += clock.seconds();
      },
      [&](const shared::RoundSummary& summary, const std::function<void()>& submitNext) {
        std::vector<shared::LineRound> reports;
        keepRound(summary, roundLines_, submitNext, room, reports);
        pointsLeft -= std::min(pointsLeft, room.points);
        Stopwatch clock;
        keep(std::move(reports), std::move(room));
        times_.consumeSeconds += clock.seconds();
      });
}

GpuRounds::~GpuRounds() { staging_.waitQuietly(); }

}  // namespace amrstream::gpu
