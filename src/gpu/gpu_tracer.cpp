#include "gpu_tracer.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstring>
#include <stdexcept>

#include "amrstream/error.hpp"
#include "flow/cpu_tracer.hpp"
#include "flow/morton_order.hpp"
#include "gpu_rounds.hpp"
#include "util/stopwatch.hpp"
#include "vector_probe.hpp"
#include "vk/buffer_transfer.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/descriptor_pool.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::gpu {

namespace {

// flow::stepsPerRound, but without history and a set round length, rounds of an eighth of the
// steps (at least 1000) when lines may be handed to the CPU, so that their ends are seen.
std::uint32_t gpuRoundSteps(const flow::TraceOptions& options, std::uint64_t slots,
                            std::size_t live) {
  if (options.cpuTailLines > 0 && !options.keepHistory && options.roundSteps == 0)
    return std::min(options.maxSteps, std::max(options.maxSteps / 8, 1000u));
  return flow::stepsPerRound(options, slots, live);
}

// The lines in the order threads take them: Morton order of their positions, or as given.
flow::Column<shared::LineState> threadOrder(std::span<const shared::LineState> lines,
                                            bool spatial) {
  if (!spatial) return {lines.begin(), lines.end()};
  flow::Column<glm::vec3> positions(lines.size());
  tbb::parallel_for(std::size_t(0), lines.size(), [&](std::size_t i) {
    positions[i] = glm::vec3(lines[i].anchor) + lines[i].offset;
  });
  const std::vector<std::uint32_t> order = flow::mortonOrder(positions);
  flow::Column<shared::LineState> ordered(lines.size());
  tbb::parallel_for(std::size_t(0), order.size(),
                    [&](std::size_t k) { ordered[k] = lines[order[k]]; });
  return ordered;
}

VkDeviceSize largestDeviceHeap(const vk::Context& ctx) {
  VkDeviceSize bytes = 0;
  const VkPhysicalDeviceMemoryProperties& memory = ctx.memoryProperties();
  for (std::uint32_t i = 0; i < memory.memoryHeapCount; ++i)
    if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
      bytes = std::max(bytes, memory.memoryHeaps[i].size);
  return bytes;
}

// The largest device-local heap, or the memory ledger's limit where that is less.
VkDeviceSize deviceLocalBytes(const vk::Context& ctx) {
  const VkDeviceSize heap = largestDeviceHeap(ctx);
  const std::optional<VkDeviceSize> limit = ctx.memoryLedger().limit();
  return limit ? std::min(heap, *limit) : heap;
}

// Dual cells take 8 times the values' memory (10 times with their padding on the cloud); they
// make samples faster where one line's latency or the ray tracing pipeline bounds the kernel
// (docs/performance-notes.md, "Dual cells read through their address"). The kernels read them
// through a buffer device address, and they take at most a quarter of the device's memory.
bool useDualValues(const vk::Context& ctx, const flow::VectorVolume& volume,
                   std::optional<bool> asked) {
  if (!asked.value_or(ctx.properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU)) return false;
  if (!VolumeBuffers::addressesDualValues(ctx) || !VolumeBuffers::canHoldDualValues(volume))
    return false;
  return VolumeBuffers::dualValueBytes(volume) <= deviceLocalBytes(ctx) / 4;
}

Backend gpuBackend(Backend backend) {
  if (backend == Backend::Cpu) throw std::invalid_argument("GpuTracer: cpu is not a GPU backend");
  return backend;
}

}  // namespace

KernelSettings runKernelSettings(Backend backend, const flow::VectorVolume& volume,
                                 std::uint64_t particleSteps) {
  // Steps a byte of dual cells must serve: the ray tracing pipeline gains 1.3x to 1.5x a step
  // from them, the compute kernels 1.1x where the device is full of lines.
  const double stepsPerByte = backend == Backend::Pipeline ? 0.5 : 10.0;
  KernelSettings settings = defaultKernelSettings(backend);
  if (double(particleSteps) < stepsPerByte * double(VolumeBuffers::dualValueBytes(volume)))
    settings.dualValues = false;
  return settings;
}

GpuTracer::GpuTracer(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume)
    : GpuTracer(ctx, backend, volume, defaultKernelSettings(backend)) {}

GpuTracer::GpuTracer(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume,
                     const KernelSettings& settings)
    : ctx_(&ctx),
      volume_(&volume),
      staging_(std::make_unique<StagingRing>(ctx)),
      device_(ctx, gpuBackend(backend), volume, setup_,
              useDualValues(ctx, volume, settings.dualValues)),
      settings_(settings) {
  settings_.deepPositions = volume.deepPositions();
  settings_.dualValues = device_.dualValues.size() > 0;
  settings_.rk4SampleLoop =
      backend == Backend::Pipeline ||
      settings.rk4SampleLoop.value_or(ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU);
  Stopwatch clock;
  kernel_ = createTraceKernel(ctx, backend, KernelProgram::Trace, settings_);
  const std::uint32_t spread = settings.spreadThreads.value_or(
      ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? 0 : residentThreads(backend));
  settings_.spreadThreads =
      static_cast<std::uint32_t>(std::min<std::uint64_t>(spread, mostInvocations()));
  roundKernels_ = createRoundKernels(ctx);
  gatherKernel_ = createGatherKernel(ctx);
  // Lavapipe compiles a kernel at its first dispatch (seconds of LLVM), which belongs to the
  // setup; a GPU's driver compiled it with the pipeline.
  if (ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) compileByDispatch();
  setup_.pipelineSeconds = clock.seconds();
}

void GpuTracer::compileByDispatch() {
  RoundBuffers buffers(*ctx_, 1, 2, volume_->channelCount(), false, volume_->deepPositions());
  GpuRounds(*ctx_, kernel_, roundKernels_, device_, *volume_, {}, flow::TraceOptions{}, buffers,
            *staging_, false)
      .compileByDispatch();
}

const TraceKernel& GpuTracer::kernelFor(const flow::TraceOptions& options) {
  if (options.integrator == settings_.integrator) return kernel_;
  auto found = otherKernels_.find(options.integrator);
  if (found == otherKernels_.end()) {
    KernelSettings settings = settings_;
    settings.integrator = options.integrator;
    found = otherKernels_
                .emplace(options.integrator,
                         createTraceKernel(*ctx_, kernel_.backend, KernelProgram::Trace, settings))
                .first;
  }
  return found->second;
}

flow::RoundCosts GpuTracer::roundCosts(const flow::TraceOptions& options) const {
  flow::RoundCosts costs = RoundBuffers::costs(volume_->channelCount(), options.vorticity);
  // Device memory is quick to make; the host's share is the staging ring's few pinned slots.
  // Longer rounds mean fewer runs of points per line for the host to keep track of.
  const VkDeviceSize deviceLocal = largestDeviceHeap(*ctx_);
  costs.mostBudget = std::min<std::uint64_t>(std::uint64_t(8) << 30, deviceLocal / 4);
  // A software device's memory is the host's, which the collected traces need.
  if (ctx_->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU)
    costs.mostBudget = std::uint64_t(2) << 30;
  costs.stepsPerLine = 128;
  return costs;
}

std::uint64_t GpuTracer::mostInvocations() const {
  return std::uint64_t(ctx_->limits().maxComputeWorkGroupCount[0]) *
         std::min<std::uint32_t>(kernel_.workgroupSize, 1u << 30);
}

std::size_t GpuTracer::linesPerBatch(const flow::TraceOptions& options, std::size_t lines) const {
  const flow::RoundCosts costs = roundCosts(options);
  const VkPhysicalDeviceLimits& limits = ctx_->limits();
  // A batch's smallest round (2 slots per line with history) must fit the storage buffer range.
  const std::uint64_t slotsPerLine = options.keepHistory ? 2 : 1;
  const std::uint64_t widest =
      std::max<std::uint64_t>(sizeof(glm::vec3), volume_->channelCount() * sizeof(float));
  const std::uint64_t byRange = limits.maxStorageBufferRange / (widest * slotsPerLine);
  std::size_t batch = flow::linesPerBatch(options, costs, lines);
  batch = std::min<std::uint64_t>({batch, byRange, mostInvocations()});
  if (batchLimit_ > 0) batch = std::min(batch, batchLimit_);
  return std::max<std::size_t>(1, batch);
}

std::uint64_t GpuTracer::pointSlots(const flow::TraceOptions& options,
                                    std::size_t batchLines) const {
  const flow::RoundCosts costs = roundCosts(options);
  const std::uint64_t widest =
      std::max<std::uint64_t>(sizeof(glm::vec3), volume_->channelCount() * sizeof(float));
  const std::uint64_t byRange = ctx_->limits().maxStorageBufferRange / widest;
  return std::min(flow::pointSlots(options, costs, batchLines), byRange);
}

flow::TraceSet GpuTracer::trace(std::span<const glm::dvec3> seeds,
                                const flow::TraceOptions& options,
                                const flow::TraceProgress& progress) {
  flow::StoredTraces rounds = traceToRounds(seeds, options, progress);
  Stopwatch clock;
  flow::TraceSet traces = std::move(rounds).assemble();
  lastRun_.assembleSeconds = clock.seconds();
  return traces;
}

void GpuTracer::traceBatches(std::span<const shared::LineState> states,
                             const flow::TraceOptions& options,
                             const std::function<void(GpuRounds&, const StepsFor&)>& run) {
  const std::size_t lines = states.size();
  const std::size_t batch = linesPerBatch(options, lines);
  for (std::size_t first = 0; first < lines; first += batch) {
    const std::size_t count = std::min(batch, lines - first);
    Stopwatch clock;
    const std::uint64_t slots = pointSlots(options, count);
    const std::size_t channels = volume_->channelCount();
    const bool regionIds = volume_->deepPositions();
    if (!roundBuffers_ ||
        !roundBuffers_->fits(count, slots, channels, options.vorticity, regionIds)) {
      roundBuffers_.reset();
      roundBuffers_ = std::make_unique<RoundBuffers>(*ctx_, count, slots, channels,
                                                     options.vorticity, regionIds);
    }
    lastRun_.buffersSeconds += clock.seconds();
    clock.restart();
    const flow::Column<shared::LineState> ordered =
        threadOrder(states.subspan(first, count), spatialOrder_);
    GpuRounds rounds(*ctx_, kernelFor(options), roundKernels_, device_, *volume_, ordered, options,
                     *roundBuffers_, *staging_, timeKernels_);
    rounds.spreadLines(*settings_.spreadThreads);
    lastRun_.linesSeconds += clock.seconds();
    run(rounds, [&](std::size_t live) { return gpuRoundSteps(options, slots, live); });
    const RoundTimes& t = rounds.times();
    const auto add = [](std::optional<double>& total, const std::optional<double>& part,
                        bool firstBatch) {
      total =
          part && (firstBatch || total) ? std::optional(total.value_or(0.0) + *part) : std::nullopt;
    };
    add(lastRun_.kernelSeconds, t.traceSeconds, first == 0);
    add(lastRun_.compactionSeconds, t.compactionSeconds, first == 0);
    ++lastRun_.batches;
    lastRun_.rounds += t.rounds;
    lastRun_.mostLanesPerLine = std::max(lastRun_.mostLanesPerLine, t.mostLanesPerLine);
    lastRun_.roundBytes = std::max(lastRun_.roundBytes, rounds.deviceBytes());
    lastRun_.submitSeconds += t.submitSeconds;
    lastRun_.roundWaitSeconds += t.roundWaitSeconds;
    lastRun_.copyWaitSeconds += t.copyWaitSeconds;
    lastRun_.unpackSeconds += t.unpackSeconds;
    lastRun_.collectSeconds += t.consumeSeconds;
  }
}

VolumeBuffers GpuTracer::releaseVolume() {
  requireVolume();
  AMRSTREAM_VK_CHECK(vkDeviceWaitIdle(ctx_->device()));
  volumeReleased_ = true;
  return std::move(device_);
}

void GpuTracer::requireVolume() const {
  if (volumeReleased_) throw std::logic_error("the tracer's volume was released");
}

flow::LinePlan GpuTracer::planRun(std::span<const glm::dvec3> seeds,
                                  const flow::TraceOptions& options) {
  requireVolume();
  lastRun_ = {};
  Stopwatch clock;
  flow::LinePlan plan = flow::planLines(*volume_, seeds, options.direction);
  lastRun_.planSeconds = clock.seconds();
  return plan;
}

flow::StoredTraces GpuTracer::traceToRounds(std::span<const glm::dvec3> seeds,
                                            const flow::TraceOptions& options,
                                            const flow::TraceProgress& progress) {
  flow::LinePlan plan = planRun(seeds, options);
  const std::size_t lines = plan.states.size();
  flow::TraceAccumulator accumulator(std::move(plan.layout), flow::traceShape(*volume_, options));
  accumulator.setMemoryLimit(options.maxResultBytes);
  const auto consume = [&](flow::RoundBlock&& block) {
    accumulator.add(std::move(block));
    if (progress) progress(accumulator.finishedLines(), lines);
  };
  std::vector<shared::LineState> tail;
  traceBatches(plan.states, options, [&](GpuRounds& rounds, const StepsFor& stepsFor) {
    rounds.runToEnd(stepsFor, consume, volume_->values.empty() ? 0 : options.cpuTailLines);
    if (rounds.liveLines() == 0) return;
    Stopwatch clock;
    const std::vector<shared::LineState> states = rounds.liveStates();
    tail.insert(tail.end(), states.begin(), states.end());
    lastRun_.tailSeconds += clock.seconds();
  });
  if (!tail.empty()) {
    std::atomic<std::size_t> finished{accumulator.finishedLines()};
    finishOnCpu(tail, options, consume, [&] {
      const std::size_t done = ++finished;
      if (progress) progress(done, lines);
    });
  }
  Stopwatch storeClock;
  flow::StoredTraces stored = accumulator.store();
  lastRun_.storeSeconds = storeClock.seconds();
  return stored;
}

void GpuTracer::finishOnCpu(std::span<const shared::LineState> lines,
                            const flow::TraceOptions& options,
                            const std::function<void(flow::RoundBlock&&)>& consume,
                            const std::function<void()>& lineEnded) {
  Stopwatch clock;
  std::uint64_t stepsBefore = 0;
  for (const shared::LineState& line : lines) stepsBefore += line.steps;
  std::uint64_t stepsAfter = 0;
  flow::traceCpuToEnd(
      *volume_, lines, options,
      [&](flow::RoundBlock&& block) {
        for (const shared::LineRound& line : block.lines)
          if (line.reason != AMRSTREAM_REASON_RUNNING) stepsAfter += line.steps;
        consume(std::move(block));
      },
      lineEnded);
  lastRun_.tailLines += lines.size();
  lastRun_.tailSteps += stepsAfter - stepsBefore;
  lastRun_.tailSeconds += clock.seconds();
}

bool GpuTracer::fitsOnDevice(const flow::TraceOptions& options, std::size_t lines) const {
  const VkDeviceSize heap = deviceLocalBytes(*ctx_);
  const std::uint64_t rounds =
      options.memoryBudget > 0 ? options.memoryBudget : roundCosts(options).mostBudget;
  const std::uint64_t taken = ctx_->memoryLedger().used() + rounds;
  const std::uint64_t left = heap > taken ? heap - taken : 0;
  const std::uint64_t pointsPerLine = options.keepHistory ? std::uint64_t(options.maxSteps) + 1 : 1;
  // As collected on the host, the region ids instead of the positions' low parts.
  const std::uint64_t bytesPerPoint =
      flow::TraceSet::bytesPerPoint(volume_->channelCount(), options.vorticity) +
      (volume_->deepPositions() ? sizeof(std::int32_t) : 0);
  const double needed = double(lines) * double(pointsPerLine) * double(bytesPerPoint);
  return needed <= 0.8 * double(left);
}

std::unique_ptr<DeviceTraces> GpuTracer::traceOnDevice(std::span<const glm::dvec3> seeds,
                                                       const flow::TraceOptions& options,
                                                       const flow::TraceProgress& progress) {
  flow::LinePlan plan = planRun(seeds, options);
  const std::size_t lines = plan.states.size();
  if (lines == 0 || !fitsOnDevice(options, lines)) return nullptr;
  flow::TraceAccumulator accumulator(std::move(plan.layout), flow::traceShape(*volume_, options));
  std::vector<KeptRound> kept;
  std::optional<StagedLayout> layout;
  traceBatches(plan.states, options, [&](GpuRounds& rounds, const StepsFor& stepsFor) {
    if (!layout) layout.emplace(*roundBuffers_, volume_->channelCount(), options.vorticity);
    rounds.runToEndOnDevice(stepsFor,
                            [&](std::vector<shared::LineRound>&& reports, KeptRound&& round) {
                              accumulator.addReports(reports);
                              kept.push_back(std::move(round));
                              if (progress) progress(accumulator.finishedLines(), lines);
                            });
  });
  Stopwatch storeClock;
  flow::TraceAccumulator::Lines traced = accumulator.takeLines();
  auto result = std::make_unique<DeviceTraces>(*ctx_, gatherKernel_, *volume_, *layout,
                                               std::move(traced.lines), std::move(kept),
                                               std::move(traced.runs), traceWindow_);
  lastRun_.storeSeconds = storeClock.seconds();
  return result;
}

std::unique_ptr<flow::RoundTracer> GpuTracer::startRounds(std::span<const shared::LineState> lines,
                                                          const flow::TraceOptions& options,
                                                          std::uint32_t mostRoundSteps) {
  const flow::Column<shared::LineState> ordered = threadOrder(lines, spatialOrder_);
  const std::uint64_t needed =
      std::uint64_t(lines.size()) * flow::pointsPerLine(options, std::max(mostRoundSteps, 1u));
  const std::uint64_t widest =
      std::max<std::uint64_t>(sizeof(glm::vec3), volume_->channelCount() * sizeof(float));
  const std::uint64_t fits = ctx_->limits().maxStorageBufferRange / widest;
  if (needed > fits)
    throw settingError("steps_per_frame",
                       fmt::format("rounds of {} steps of {} lines make {} points, more than the "
                                   "{} one device buffer holds; take fewer steps per frame",
                                   mostRoundSteps, lines.size(), needed, fits));
  auto buffers = std::make_unique<RoundBuffers>(
      *ctx_, lines.size(), std::max(pointSlots(options, lines.size()), needed),
      volume_->channelCount(), options.vorticity, volume_->deepPositions());
  auto rounds =
      std::make_unique<GpuRounds>(*ctx_, kernelFor(options), roundKernels_, device_, *volume_,
                                  ordered, options, std::move(buffers), *staging_, timeKernels_);
  rounds->spreadLines(*settings_.spreadThreads);
  return rounds;
}

flow::RoundBlock GpuTracer::advanceRound(std::vector<shared::LineState>& lines,
                                         const flow::TraceOptions& options, std::uint32_t steps,
                                         bool order) {
  requireVolume();
  if (lines.empty()) return {};
  const std::size_t channels = volume_->channelCount();
  const bool regionIds = volume_->deepPositions();
  const std::uint64_t slots =
      std::uint64_t(lines.size()) * flow::pointsPerLine(options, std::max(steps, 1u));
  if (!roundBuffers_ ||
      !roundBuffers_->fits(lines.size(), slots, channels, options.vorticity, regionIds)) {
    // Room for a quarter more, as lines handed on from other ranks come and go.
    const std::size_t room = lines.size() + lines.size() / 4;
    roundBuffers_.reset();
    roundBuffers_ = std::make_unique<RoundBuffers>(
        *ctx_, room, std::uint64_t(room) * flow::pointsPerLine(options, std::max(steps, 1u)),
        channels, options.vorticity, regionIds);
  }
  Stopwatch clock;
  if (order) {
    const flow::Column<shared::LineState> ordered = threadOrder(lines, spatialOrder_);
    lines.assign(ordered.begin(), ordered.end());
  }
  GpuRounds rounds(*ctx_, kernelFor(options), roundKernels_, device_, *volume_, lines, options,
                   *roundBuffers_, *staging_, timeKernels_);
  rounds.spreadLines(*settings_.spreadThreads);
  lastRun_.linesSeconds += clock.seconds();
  flow::RoundBlock block = rounds.advance(steps);
  lastRun_.mostLanesPerLine = std::max(lastRun_.mostLanesPerLine, rounds.times().mostLanesPerLine);
  clock.restart();
  lines = rounds.liveStates();
  lastRun_.statesSeconds += clock.seconds();
  const RoundTimes& t = rounds.times();
  if (t.traceSeconds)
    lastRun_.kernelSeconds = lastRun_.kernelSeconds.value_or(0.0) + *t.traceSeconds;
  ++lastRun_.rounds;
  lastRun_.submitSeconds += t.submitSeconds;
  lastRun_.roundWaitSeconds += t.roundWaitSeconds;
  lastRun_.copyWaitSeconds += t.copyWaitSeconds;
  lastRun_.unpackSeconds += t.unpackSeconds;
  lastRun_.roundBytes = std::max(lastRun_.roundBytes, rounds.deviceBytes());
  return block;
}

void GpuTracer::setStaging(std::size_t slots, std::uint64_t slotBytes) {
  staging_.reset();
  staging_ = std::make_unique<StagingRing>(*ctx_, slots, slotBytes);
}

std::vector<std::int32_t> GpuTracer::locate(std::span<const glm::vec3> cellPoints) {
  requireVolume();
  if (!probe_) probe_ = createTraceKernel(*ctx_, kernel_.backend, KernelProgram::LocateProbe);
  VectorProbe probe(*ctx_, *probe_, *volume_, device_);
  std::vector<flow::VectorSample> samples(cellPoints.size());
  probe.sample(cellPoints, samples);
  std::vector<std::int32_t> regions(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) regions[i] = samples[i].region;
  return regions;
}

}  // namespace amrstream::gpu
