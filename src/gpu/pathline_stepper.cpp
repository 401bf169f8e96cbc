#include "pathline_stepper.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <span>
#include <stdexcept>
#include <vector>

#include "../../shaders/glsl/shared/pathline_stage.h"
#include "../../shaders/glsl/shared/round_bindings.h"
#include "../../shaders/glsl/shared/round_params.h"
#include "../../shaders/glsl/shared/trace_codes.h"
#include "pathline_stage_comp.h"
#include "round_kernels.hpp"
#include "util/stopwatch.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/descriptor_pool.hpp"
#include "vk/descriptor_writes.hpp"
#include "vk/pipelines.hpp"
#include "vk/submission.hpp"

namespace amrstream::gpu {

namespace {

// Bytes of one particle's output in one step: its point, its vector, its status and both
// snapshots' channels.
std::size_t rowBytesPerParticle(std::size_t channels) {
  return 2 * sizeof(glm::vec3) + sizeof(std::int32_t) + 2 * channels * sizeof(float);
}

shared::PathlineFrame frameOf(const flow::VectorVolume& volume) {
  shared::PathlineFrame f{};
  f.origin = glm::vec3(volume.transform.origin);
  f.spacing = glm::vec3(volume.transform.spacing);
  for (int a = 0; a < 3; ++a)
    if (volume.periodic[a]) f.periodicAxes |= 1u << a;
  f.domainLower = volume.domain.lower;
  f.domainUpper = volume.domain.upper;
  return f;
}

template <typename T>
void copyInto(vk::Buffer& buffer, std::span<const T> values) {
  std::memcpy(buffer.mapped().data(), values.data(), values.size_bytes());
}

}  // namespace

struct PathlineStepper::Kernel {
  vk::UniqueHandle<VkDescriptorSetLayout> setLayout;
  vk::UniqueHandle<VkPipelineLayout> layout;
  vk::UniqueHandle<VkPipeline> pipeline;
};

// The particles' states, the probes' points and samples, the round's output, and the host-visible
// buffers the interval's plan arrives in.
struct PathlineStepper::Buffers {
  std::size_t particles = 0, rows = 0, scheduleSteps = 0;
  vk::Buffer interval, paramsA, paramsB, unused;
  vk::Buffer planPositions, planGroups, planSchedule;  // host-visible: the plan
  vk::Buffer schedule, groups, positions, reasons, stages, stepReasons;
  vk::Buffer cellsA, cellsB, vectorsA, vectorsB, regionsA, regionsB;
  // A round's output, host-visible; two, so that the device runs a round while the host
  // collects the last. Each step's end point's channels are sampled into the scratch buffers,
  // then copied to their row.
  struct Output {
    vk::Buffer positions, vectors, status, channelsA, channelsB;
    VkDescriptorSet stageSet = VK_NULL_HANDLE;
  };
  std::array<Output, 2> out;
  std::size_t channels = 0;
  vk::Buffer pointSummary, scratchA, scratchB;
  std::unique_ptr<vk::DescriptorPool> pool;
  VkDescriptorSet probeSetA = VK_NULL_HANDLE, probeSetB = VK_NULL_HANDLE,
                  pointSetA = VK_NULL_HANDLE, pointSetB = VK_NULL_HANDLE;
};

PathlineStepper::PathlineStepper(const vk::Context& ctx, const TraceKernel& probeKernel,
                                 std::uint64_t roundBytes, std::size_t mostParticles)
    : ctx_(&ctx),
      probeKernel_(&probeKernel),
      roundBytes_(roundBytes),
      mostParticles_(mostParticles),
      kernel_(std::make_unique<Kernel>()),
      buffers_(std::make_unique<Buffers>()) {
  std::vector<VkDescriptorSetLayoutBinding> bindings =
      vk::storageBufferBindings(AMRSTREAM_PATHLINE_BINDING_COUNT, VK_SHADER_STAGE_COMPUTE_BIT);
  bindings[AMRSTREAM_BINDING_PATHLINE_INTERVAL].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  kernel_->setLayout = vk::createDescriptorSetLayout(ctx, bindings);
  kernel_->layout =
      vk::createPipelineLayout(ctx, kernel_->setLayout.get(), sizeof(shared::PathlineStagePush),
                               VK_SHADER_STAGE_COMPUTE_BIT);
  kernel_->pipeline = vk::createComputePipeline(ctx, kernel_->layout.get(),
                                                vk::spirv(amrstream_spirv_pathline_stage_comp),
                                                nullptr, "pathline stage");
  Buffers& b = *buffers_;
  b.interval = vk::Buffer::upload(ctx, sizeof(shared::PathlineInterval),
                                  VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "pathline interval");
  for (vk::Buffer* params : {&b.paramsA, &b.paramsB})
    *params = vk::Buffer::upload(ctx, sizeof(shared::TraceParams),
                                 VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "pathline probe params");
  b.unused =
      vk::Buffer::deviceLocal(ctx, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "pathline probe unused");
}

PathlineStepper::~PathlineStepper() = default;

std::size_t PathlineStepper::mostParticles() const { return mostParticles_; }

void PathlineStepper::bind(const VectorProbe& a, const VectorProbe& b) {
  a_ = &a;
  b_ = &b;
}

void PathlineStepper::reserve(std::size_t particles, std::size_t rows, std::size_t scheduleSteps,
                              std::size_t channels) {
  Buffers& b = *buffers_;
  const vk::Context& ctx = *ctx_;
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  const VkBufferUsageFlags source = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  const VkBufferUsageFlags target = storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  bool changed = false;
  if (scheduleSteps > b.scheduleSteps) {
    const std::size_t bytes = scheduleSteps * sizeof(shared::PathlineStep);
    b.planSchedule = vk::Buffer::upload(ctx, bytes, source, "pathline plan schedule");
    b.schedule = vk::Buffer::deviceLocal(ctx, bytes, target, "pathline schedule");
    b.scheduleSteps = scheduleSteps;
    changed = true;
  }
  if (particles > b.particles) {
    const std::size_t n = particles;
    const auto vectors = [&](std::size_t per, const char* name) {
      return vk::Buffer::deviceLocal(ctx, n * per * sizeof(glm::vec3), target, name);
    };
    const auto integers = [&](const char* name) {
      return vk::Buffer::deviceLocal(ctx, n * sizeof(std::int32_t), target, name);
    };
    b.planPositions = vk::Buffer::upload(ctx, n * sizeof(glm::vec3), source, "pathline plan");
    b.planGroups = vk::Buffer::upload(ctx, n * sizeof(std::uint32_t), source, "pathline plan");
    b.positions = vectors(1, "pathline positions");
    b.groups = integers("pathline groups");
    b.reasons = integers("pathline reasons");
    b.stages = vectors(4, "pathline stages");
    b.stepReasons = integers("pathline step reasons");
    b.cellsA = vectors(1, "pathline cells A");
    b.cellsB = vectors(1, "pathline cells B");
    b.vectorsA = vectors(1, "pathline vectors A");
    b.vectorsB = vectors(1, "pathline vectors B");
    b.regionsA = integers("pathline regions A");
    b.regionsB = integers("pathline regions B");
    b.particles = n;
    b.rows = 0;
    changed = true;
  }
  if (rows > b.rows || channels != b.channels) {
    const std::size_t slots = rows * b.particles;
    const std::size_t scratch = b.particles * channels * sizeof(float);
    for (Buffers::Output& out : b.out) {
      out = {};
      out.positions =
          vk::Buffer::readback(ctx, slots * sizeof(glm::vec3), storage, "pathline points");
      out.vectors =
          vk::Buffer::readback(ctx, slots * sizeof(glm::vec3), storage, "pathline vectors");
      out.status =
          vk::Buffer::readback(ctx, slots * sizeof(std::int32_t), storage, "pathline status");
      if (channels == 0) continue;
      const VkBufferUsageFlags copied = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
      out.channelsA = vk::Buffer::readback(ctx, rows * scratch, copied, "pathline channels A");
      out.channelsB = vk::Buffer::readback(ctx, rows * scratch, copied, "pathline channels B");
    }
    b.rows = rows;
    b.channels = channels;
    if (channels > 0) {
      b.scratchA = vk::Buffer::deviceLocal(ctx, scratch, storage | source, "pathline channels");
      b.scratchB = vk::Buffer::deviceLocal(ctx, scratch, storage | source, "pathline channels");
      b.pointSummary =
          vk::Buffer::upload(ctx, sizeof(shared::RoundSummary), storage, "pathline point count");
    }
    changed = true;
  }
  if (!changed && b.pool) return;
  const std::array<VkDescriptorPoolSize, 3> sizes{
      {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
       {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
        std::max<std::uint32_t>(AMRSTREAM_PATHLINE_BINDING_COUNT, AMRSTREAM_TRACE_BINDING_COUNT)},
       {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1}}};
  b.pool = std::make_unique<vk::DescriptorPool>(ctx, 6, sizes);
  b.probeSetA = b.pool->allocate(probeKernel_->setLayout.get());
  b.probeSetB = b.pool->allocate(probeKernel_->setLayout.get());
  for (Buffers::Output& out : b.out) {
    out.stageSet = b.pool->allocate(kernel_->setLayout.get());
    vk::DescriptorWrites("pathline stage", AMRSTREAM_PATHLINE_BINDING_COUNT)
        .set(AMRSTREAM_BINDING_PATHLINE_INTERVAL, vk::uniformTarget(b.interval))
        .set(AMRSTREAM_BINDING_PATHLINE_SCHEDULE, b.schedule)
        .set(AMRSTREAM_BINDING_PATHLINE_GROUPS, b.groups)
        .set(AMRSTREAM_BINDING_PATHLINE_POSITIONS, b.positions)
        .set(AMRSTREAM_BINDING_PATHLINE_REASONS, b.reasons)
        .set(AMRSTREAM_BINDING_PATHLINE_STAGES, b.stages)
        .set(AMRSTREAM_BINDING_PATHLINE_STEP_REASONS, b.stepReasons)
        .set(AMRSTREAM_BINDING_PATHLINE_CELLS_A, b.cellsA)
        .set(AMRSTREAM_BINDING_PATHLINE_CELLS_B, b.cellsB)
        .set(AMRSTREAM_BINDING_PATHLINE_VECTORS_A, b.vectorsA)
        .set(AMRSTREAM_BINDING_PATHLINE_VECTORS_B, b.vectorsB)
        .set(AMRSTREAM_BINDING_PATHLINE_REGIONS_A, b.regionsA)
        .set(AMRSTREAM_BINDING_PATHLINE_REGIONS_B, b.regionsB)
        .set(AMRSTREAM_BINDING_PATHLINE_OUT_POSITIONS, out.positions)
        .set(AMRSTREAM_BINDING_PATHLINE_OUT_VECTORS, out.vectors)
        .set(AMRSTREAM_BINDING_PATHLINE_OUT_STATUS, out.status)
        .write(ctx, out.stageSet);
  }
  if (channels == 0) return;
  if (!pointData_) pointData_ = std::make_unique<PointDataKernel>(createPointDataKernel(ctx));
  b.pointSetA = b.pool->allocate(pointData_->setLayout.get());
  b.pointSetB = b.pool->allocate(pointData_->setLayout.get());
}

void PathlineStepper::move(const flow::IntervalPlan& plan,
                           const std::function<void(const flow::StepRows&)>& collect) {
  const std::size_t n = plan.positions.size();
  if (n == 0 || plan.stepCount == 0) return;
  if (n > mostParticles_ || !a_ || !b_)
    throw std::logic_error("PathlineStepper::move: too many particles, or no snapshots bound");
  const vk::Context& ctx = *ctx_;
  const std::size_t rows = std::clamp<std::size_t>(
      roundBytes_ / (n * rowBytesPerParticle(a_->volume().channelCount())), 1, plan.stepCount);
  const std::size_t channels = a_->volume().channelCount();
  if (b_->volume().channelCount() != channels)
    throw std::logic_error("PathlineStepper::move: the snapshots have other channels");
  reserve(n, rows, plan.schedule.size(), channels);
  Buffers& b = *buffers_;
  writeProbeSet(ctx, b.probeSetA, a_->device(), b.paramsA, b.cellsA, b.vectorsA, b.regionsA,
                b.unused);
  writeProbeSet(ctx, b.probeSetB, b_->device(), b.paramsB, b.cellsB, b.vectorsB, b.regionsB,
                b.unused);
  if (channels > 0) {
    const shared::RoundSummary summary{std::uint32_t(n), 0, {0, 0, 0}};  // the point count
    std::memcpy(b.pointSummary.mapped().data(), &summary, sizeof(summary));
    writePointDataSet(ctx, b.pointSetA, a_->device(),
                      {b.pointSummary, b.cellsA, b.regionsA, b.scratchA, b.unused});
    writePointDataSet(ctx, b.pointSetB, b_->device(),
                      {b.pointSummary, b.cellsB, b.regionsB, b.scratchB, b.unused});
  }

  shared::PathlineInterval interval{};
  interval.a = frameOf(a_->volume());
  interval.b = frameOf(b_->volume());
  interval.particleCount = std::uint32_t(n);
  interval.stepCount = plan.stepCount;
  std::memcpy(b.interval.mapped().data(), &interval, sizeof(interval));
  for (const auto& [params, probe] : {std::pair{&b.paramsA, a_}, std::pair{&b.paramsB, b_}}) {
    const shared::TraceParams p = probeParams(probe->volume(), n);
    std::memcpy(params->mapped().data(), &p, sizeof(p));
  }
  copyInto(b.planPositions, plan.positions);
  copyInto(b.planGroups, plan.groups);
  copyInto(b.planSchedule, plan.schedule);

  const TraceKernel& probe = *probeKernel_;
  const bool rayTracing = probe.bindPoint == VK_PIPELINE_BIND_POINT_RAY_TRACING_KHR;
  VkPipelineStageFlags shaders = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
  if (rayTracing) shaders |= VK_PIPELINE_STAGE_RAY_TRACING_SHADER_BIT_KHR;
  const vk::Access written{shaders, VK_ACCESS_SHADER_WRITE_BIT};
  const vk::Access used{shaders, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
  const std::uint32_t stageGroups =
      std::uint32_t((n + AMRSTREAM_PATHLINE_GROUP - 1) / AMRSTREAM_PATHLINE_GROUP);

  const auto stage = [&](VkCommandBuffer cmd, const Buffers::Output& out, std::uint32_t which,
                         std::uint32_t step, std::uint32_t row) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernel_->pipeline.get());
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, kernel_->layout.get(), 0, 1,
                            &out.stageSet, 0, nullptr);
    const shared::PathlineStagePush push{which, step, row};
    vkCmdPushConstants(cmd, kernel_->layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push),
                       &push);
    vkCmdDispatch(cmd, stageGroups, 1, 1);
    vk::memoryBarrier(cmd, written, used);
    ++times_.dispatches;
  };
  const auto probes = [&](VkCommandBuffer cmd) {
    for (const VkDescriptorSet set : {b.probeSetA, b.probeSetB}) {
      recordProbe(ctx, probe, cmd, set, n);
      times_.dispatches += 1;
    }
    vk::memoryBarrier(cmd, written, used);
  };
  // The channels at the end points the probes located, into row `row` of the output.
  const std::size_t rowChannelBytes = n * channels * sizeof(float);
  const auto pointData = [&](VkCommandBuffer cmd, const Buffers::Output& out, std::uint32_t row) {
    const shared::PointDataParams params{
        glm::vec3(0.0f), std::uint32_t(channels), 0u,
        a_->volume().interpolant == flow::Interpolant::Linear ? 1u : 0u, 0u};
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pointData_->pipeline.get());
    vkCmdPushConstants(cmd, pointData_->layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                       sizeof(params), &params);
    for (const VkDescriptorSet set : {b.pointSetA, b.pointSetB}) {
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pointData_->layout.get(), 0, 1,
                              &set, 0, nullptr);
      vkCmdDispatch(
          cmd, std::uint32_t((n + AMRSTREAM_POINT_DATA_GROUP - 1) / AMRSTREAM_POINT_DATA_GROUP), 1,
          1);
      times_.dispatches += 1;
    }
    vk::memoryBarrier(cmd, written, vk::access::kTransferRead);
    const VkBufferCopy region{0, row * rowChannelBytes, rowChannelBytes};
    vkCmdCopyBuffer(cmd, b.scratchA.handle(), out.channelsA.handle(), 1, &region);
    vkCmdCopyBuffer(cmd, b.scratchB.handle(), out.channelsB.handle(), 1, &region);
    // The next row's kernels overwrite the scratch buffers the copies read.
    vk::memoryBarrier(cmd, vk::access::kTransferRead, used);
  };
  // Round `round`'s steps, into output round % 2.
  const auto record = [&](VkCommandBuffer cmd, std::uint32_t firstStep, std::uint32_t roundRows,
                          const Buffers::Output& out) {
    // The host's writes, and the last round's, come first.
    vk::memoryBarrier(cmd, vk::access::kHostWrite, vk::access::kAny);
    vk::memoryBarrier(cmd, written, used);
    if (firstStep == 0) {
      const auto copy = [&](const vk::Buffer& from, const vk::Buffer& to, std::size_t bytes) {
        const VkBufferCopy region{0, 0, bytes};
        vkCmdCopyBuffer(cmd, from.handle(), to.handle(), 1, &region);
      };
      copy(b.planPositions, b.positions, n * sizeof(glm::vec3));
      copy(b.planGroups, b.groups, n * sizeof(std::uint32_t));
      copy(b.planSchedule, b.schedule, plan.schedule.size_bytes());
      vkCmdFillBuffer(cmd, b.reasons.handle(), 0, n * sizeof(std::int32_t),
                      AMRSTREAM_REASON_RUNNING);
      // No region hints in the interval's new snapshots (locate_probe.glsl).
      for (const vk::Buffer* hints : {&b.regionsA, &b.regionsB})
        vkCmdFillBuffer(cmd, hints->handle(), 0, n * sizeof(std::int32_t), ~0u);
      vk::memoryBarrier(cmd, vk::access::kTransferWrite, used);
      stage(cmd, out, AMRSTREAM_PATHLINE_START, 0, 0);
      probes(cmd);
      stage(cmd, out, AMRSTREAM_PATHLINE_K1, 0, 0);
    }
    for (std::uint32_t row = 0; row < roundRows; ++row) {
      const std::uint32_t step = firstStep + row;
      probes(cmd);
      stage(cmd, out, AMRSTREAM_PATHLINE_K2, step, row);
      probes(cmd);
      stage(cmd, out, AMRSTREAM_PATHLINE_K3, step, row);
      probes(cmd);
      stage(cmd, out, AMRSTREAM_PATHLINE_K4, step, row);
      probes(cmd);
      if (channels > 0) pointData(cmd, out, row);
      stage(cmd, out, AMRSTREAM_PATHLINE_END, step, row);
    }
    vk::memoryBarrier(cmd, vk::access::kAnyWrite, vk::access::kHostRead);
  };
  const auto rowsFrom = [&](std::uint32_t firstStep) {
    return std::min<std::uint32_t>(std::uint32_t(rows), plan.stepCount - firstStep);
  };
  const auto hand = [&](std::uint32_t firstStep, const Buffers::Output& out) {
    const std::uint32_t roundRows = rowsFrom(firstStep);
    const std::size_t slots = std::size_t(roundRows) * n;
    for (const vk::Buffer* buffer : {&out.positions, &out.vectors, &out.status})
      buffer->invalidateMapped();
    flow::StepRows stepRows;
    stepRows.firstStep = firstStep;
    stepRows.rows = roundRows;
    stepRows.status = {reinterpret_cast<const std::int32_t*>(out.status.mapped().data()), slots};
    stepRows.positions = {reinterpret_cast<const glm::vec3*>(out.positions.mapped().data()), slots};
    stepRows.vectors = {reinterpret_cast<const glm::vec3*>(out.vectors.mapped().data()), slots};
    stepRows.channelCount = channels;
    if (channels > 0) {
      out.channelsA.invalidateMapped();
      out.channelsB.invalidateMapped();
      stepRows.channelsA = {reinterpret_cast<const float*>(out.channelsA.mapped().data()),
                            slots * channels};
      stepRows.channelsB = {reinterpret_cast<const float*>(out.channelsB.mapped().data()),
                            slots * channels};
    }
    collect(stepRows);
  };

  // Round k + 1 runs on the device while the host collects round k.
  std::array<vk::Submission, 2> submissions{vk::Submission(ctx), vk::Submission(ctx)};
  const auto submit = [&](std::uint32_t round) {
    const std::uint32_t firstStep = round * std::uint32_t(rows);
    const Buffers::Output& out = b.out[round % 2];
    submissions[round % 2].submit(
        [&](VkCommandBuffer cmd) { record(cmd, firstStep, rowsFrom(firstStep), out); });
    ++times_.rounds;
  };
  const std::uint32_t rounds = std::uint32_t((plan.stepCount + rows - 1) / rows);
  submit(0);
  for (std::uint32_t round = 0; round < rounds; ++round) {
    if (round + 1 < rounds) submit(round + 1);
    Stopwatch clock;
    submissions[round % 2].wait();
    times_.deviceSeconds += clock.seconds();
    clock.restart();
    hand(round * std::uint32_t(rows), b.out[round % 2]);
    times_.collectSeconds += clock.seconds();
  }
}

}  // namespace amrstream::gpu
