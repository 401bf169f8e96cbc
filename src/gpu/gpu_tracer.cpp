#include "gpu_tracer.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <numeric>
#include <utility>
#include <stdexcept>

#include "vk/buffer_transfer.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "util/stopwatch.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::gpu {

namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

std::vector<VkAabbPositionsKHR> regionBoxes(const bricks::RegionSet& regions) {
  std::vector<VkAabbPositionsKHR> boxes(regions.regions.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const shared::Region& r = regions.regions[i];
    boxes[i] = {r.lower.x, r.lower.y, r.lower.z, r.upper.x, r.upper.y, r.upper.z};
  }
  return boxes;
}

// Interleaves the low 10 bits of x with two zero bits after each.
std::uint32_t spreadBits(std::uint32_t x) {
  x &= 0x3ff;
  x = (x | (x << 16)) & 0x030000ff;
  x = (x | (x << 8)) & 0x0300f00f;
  x = (x | (x << 4)) & 0x030c30c3;
  x = (x | (x << 2)) & 0x09249249;
  return x;
}

// The seeds' indices sorted by the Morton code of their positions on a 1024^3 grid over their
// bounding box.
std::vector<std::uint32_t> mortonOrder(std::span<const glm::vec3> points) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 scale = 1023.0f / glm::max(hi - lo, glm::vec3(1e-20f));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed(points.size());
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
    const glm::uvec3 q(glm::clamp((points[i] - lo) * scale, glm::vec3(0.0f), glm::vec3(1023.0f)));
    keyed[i] = {spreadBits(q.x) | (spreadBits(q.y) << 1) | (spreadBits(q.z) << 2),
                static_cast<std::uint32_t>(i)};
  });
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].second;
  return order;
}

VkDescriptorBufferInfo whole(const vk::Buffer& buffer) {
  return {buffer.handle(), 0, VK_WHOLE_SIZE};
}

}  // namespace

GpuTracer::GpuTracer(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume)
    : GpuTracer(ctx, backend, volume, defaultKernelSettings(backend)) {}

GpuTracer::GpuTracer(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume,
                     const KernelSettings& settings)
    : ctx_(&ctx), volume_(&volume), timer_(ctx) {
  if (backend == Backend::Cpu) throw std::invalid_argument("GpuTracer: cpu is not a GPU backend");
  Stopwatch clock;
  bricks_ = vk::uploadToDeviceLocal(ctx, volume.bricks, kStorage, "bricks");
  values_ = vk::uploadToDeviceLocal(ctx, volume.values, kStorage, "vector values");
  regions_ = vk::uploadToDeviceLocal(ctx, volume.regions.regions, kStorage, "regions");
  regionBricks_ =
      vk::uploadToDeviceLocal(ctx, volume.regions.regionBricks, kStorage, "region bricks");
  setup_.uploadSeconds = clock.seconds();
  setup_.volumeBytes = bricks_.size() + values_.size() + regions_.size() + regionBricks_.size();

  clock.restart();
  if (backend == Backend::Compute) {
    tree_ = vk::uploadToDeviceLocal(ctx, volume.regions.tree, kStorage, "region tree");
    setup_.structureBytes = tree_.size();
  } else {
    scene_ = vk::buildAabbScene(ctx, regionBoxes(volume.regions), "regions");
    setup_.structureBytes = scene_->tlas.size();
    for (const vk::AabbBlas& blas : scene_->blases) setup_.structureBytes += blas.structure.size();
  }
  setup_.structureSeconds = clock.seconds();

  clock.restart();
  kernel_ = createTraceKernel(ctx, backend, KernelProgram::Trace, settings);
  setup_.pipelineSeconds = clock.seconds();
}

std::size_t GpuTracer::seedsPerChunk(std::uint32_t capacity) const {
  const std::vector<VkDeviceSize> heaps = ctx_->memoryHeapSizes();
  const VkDeviceSize largestHeap =
      heaps.empty() ? 0 : *std::max_element(heaps.begin(), heaps.end());
  const std::size_t byRange =
      ctx_->limits().maxStorageBufferRange / (std::size_t(capacity) * sizeof(glm::vec3));
  const std::size_t byMemory =
      largestHeap / 4 / (std::size_t(capacity) * flow::TraceSet::kBytesPerPoint);
  const std::size_t byDispatch =
      std::size_t(ctx_->limits().maxComputeWorkGroupCount[0]) * kernel_.workgroupSize;
  const std::size_t chunk = std::min({byRange, byMemory, byDispatch});
  return chunkLimit_ > 0 ? std::min(chunk, chunkLimit_) : chunk;
}

flow::TraceSet GpuTracer::trace(std::span<const glm::dvec3> seeds,
                                const flow::TraceOptions& options,
                                const std::function<void(std::size_t)>& progress) {
  flow::TraceSet out;
  out.resize(static_cast<std::uint32_t>(seeds.size()),
             options.keepHistory ? options.maxSteps + 1 : 1);
  out.vectorName = volume_->vectorName;
  const std::size_t chunk = seedsPerChunk(out.capacity);
  lastRun_ = {};
  if (chunk == 0)
    throw std::length_error(fmt::format(
        "one trace of {} points ({:.1f} MiB of positions) does not fit in the device's storage "
        "buffer range of {:.1f} MiB; lower --steps or use --endpoints-only",
        out.capacity, double(out.capacity) * sizeof(glm::vec3) / 0x1p20,
        double(ctx_->limits().maxStorageBufferRange) / 0x1p20));
  for (std::size_t first = 0; first < seeds.size(); first += chunk) {
    const std::size_t count = std::min(chunk, seeds.size() - first);
    traceChunk(seeds.subspan(first, count), options, out, static_cast<std::uint32_t>(first));
    if (progress) progress(first + count);
  }
  return out;
}

GpuTracer::Outputs GpuTracer::makeOutputs(std::size_t seeds, std::uint32_t capacity) const {
  const vk::Context& ctx = *ctx_;
  const std::size_t points = seeds * std::size_t(capacity);
  const VkBufferUsageFlags usage = kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
  return {vk::Buffer::deviceLocal(ctx, points * sizeof(glm::vec3), usage, "positions"),
          vk::Buffer::deviceLocal(ctx, points * sizeof(float), usage, "times"),
          vk::Buffer::deviceLocal(ctx, points * sizeof(glm::vec3), usage, "vectors"),
          vk::Buffer::deviceLocal(ctx, seeds * sizeof(std::uint32_t), usage, "point counts"),
          vk::Buffer::deviceLocal(ctx, seeds * sizeof(std::int32_t), usage, "reasons")};
}

std::optional<double> GpuTracer::dispatch(const TraceKernel& kernel,
                                          const shared::TraceParams& params,
                                          std::span<const glm::vec3> seedCells,
                                          const Outputs& outputs) const {
  const vk::Context& ctx = *ctx_;
  vk::Buffer paramsBuffer =
      vk::Buffer::upload(ctx, sizeof(params), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, "trace params");
  std::memcpy(paramsBuffer.mapped().data(), &params, sizeof(params));
  const vk::Buffer seedBuffer = vk::uploadToDeviceLocal(ctx, seedCells, kStorage, "seeds");

  // One descriptor set for this dispatch.
  std::array<VkDescriptorPoolSize, 3> poolSizes{
      {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
       {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kTraceBindingCount - 1},
       {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, 1}}};
  VkDescriptorPoolCreateInfo poolInfo{};
  poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = kernel.backend == Backend::Compute ? 2 : 3;
  poolInfo.pPoolSizes = poolSizes.data();
  VkDescriptorPool rawPool;
  AMRSTREAM_VK_CHECK(vkCreateDescriptorPool(ctx.device(), &poolInfo, nullptr, &rawPool));
  const vk::UniqueHandle<VkDescriptorPool> pool(ctx.device(), rawPool);
  VkDescriptorSetAllocateInfo allocInfo{};
  allocInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  allocInfo.descriptorPool = rawPool;
  allocInfo.descriptorSetCount = 1;
  const VkDescriptorSetLayout setLayout = kernel.setLayout.get();
  allocInfo.pSetLayouts = &setLayout;
  VkDescriptorSet set;
  AMRSTREAM_VK_CHECK(vkAllocateDescriptorSets(ctx.device(), &allocInfo, &set));

  const std::array<VkDescriptorBufferInfo, kTraceBindingCount> buffers{
      whole(paramsBuffer),      whole(bricks_),
      whole(values_),           whole(regions_),
      whole(regionBricks_),     whole(seedBuffer),
      whole(outputs.positions), whole(outputs.times),
      whole(outputs.vectors),   whole(outputs.pointCounts),
      whole(outputs.reasons),   whole(tree_)};
  std::array<VkWriteDescriptorSet, kTraceBindingCount> writes{};
  for (std::uint32_t i = 0; i < kTraceBindingCount; ++i) {
    writes[i] = {};
    writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[i].dstSet = set;
    writes[i].dstBinding = i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType =
        i == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &buffers[i];
  }
  VkWriteDescriptorSetAccelerationStructureKHR sceneWrite{};
  sceneWrite.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR;
  VkAccelerationStructureKHR tlas = VK_NULL_HANDLE;
  if (scene_) {
    tlas = scene_->tlas.handle();
    sceneWrite.accelerationStructureCount = 1;
    sceneWrite.pAccelerationStructures = &tlas;
    writes[kLocateBinding].descriptorType = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
    writes[kLocateBinding].pBufferInfo = nullptr;
    writes[kLocateBinding].pNext = &sceneWrite;
  }
  vkUpdateDescriptorSets(ctx.device(), kTraceBindingCount, writes.data(), 0, nullptr);

  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    vkCmdBindPipeline(cmd, kernel.bindPoint, kernel.pipeline.get());
    vkCmdBindDescriptorSets(cmd, kernel.bindPoint, kernel.pipelineLayout.get(), 0, 1, &set, 0,
                            nullptr);
    timer_.start(cmd);
    const std::uint32_t n = static_cast<std::uint32_t>(seedCells.size());
    if (kernel.backend == Backend::Pipeline) {
      const ShaderBindingTable& sbt = kernel.bindingTable;
      ctx.functions().vkCmdTraceRaysKHR(cmd, &sbt.raygen, &sbt.miss, &sbt.hit, &sbt.callable, n, 1,
                                        1);
    } else {
      vkCmdDispatch(cmd, (n + kernel.workgroupSize - 1) / kernel.workgroupSize, 1, 1);
    }
    timer_.stop(cmd);
    vk::memoryBarrier(cmd, vk::access::kAnyWrite, vk::access::kAny);
  });
  return timer_.seconds();
}

std::vector<std::int32_t> GpuTracer::locate(std::span<const glm::vec3> cellPoints) {
  if (!probe_) probe_ = createTraceKernel(*ctx_, kernel_.backend, KernelProgram::LocateProbe);
  const shared::TraceParams params =
      flow::makeTraceParams(*volume_, flow::TraceOptions{}, cellPoints.size());
  const Outputs outputs = makeOutputs(cellPoints.size(), 1);
  dispatch(*probe_, params, cellPoints, outputs);
  return vk::readBackAs<std::int32_t>(*ctx_, outputs.reasons);
}

void GpuTracer::traceChunk(std::span<const glm::dvec3> seeds, const flow::TraceOptions& options,
                           flow::TraceSet& out, std::uint32_t firstSeed) {
  const vk::Context& ctx = *ctx_;
  const shared::TraceParams params = flow::makeTraceParams(*volume_, options, seeds.size());
  std::vector<glm::vec3> seedCells(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i)
    seedCells[i] = glm::vec3(volume_->transform.toCellUnits(seeds[i]));
  // Thread k traces seed order[k].
  std::vector<std::uint32_t> order(seeds.size());
  std::iota(order.begin(), order.end(), 0u);
  if (spatialOrder_) {
    order = mortonOrder(seedCells);
    std::vector<glm::vec3> sorted(seeds.size());
    for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = seedCells[order[k]];
    seedCells = std::move(sorted);
  }
  const Outputs outputs = makeOutputs(seeds.size(), params.capacity);
  const std::optional<double> kernelSeconds = dispatch(kernel_, params, seedCells, outputs);
  lastRun_.kernelSeconds =
      kernelSeconds ? std::optional(lastRun_.kernelSeconds.value_or(0.0) + *kernelSeconds)
                    : std::nullopt;
  ++lastRun_.chunks;
  lastRun_.chunkBytes =
      std::max<std::uint64_t>(lastRun_.chunkBytes, seedCells.size() * sizeof(glm::vec3) +
                                                       outputs.positions.size() +
                                                       outputs.times.size() +
                                                       outputs.vectors.size() +
                                                       outputs.pointCounts.size() +
                                                       outputs.reasons.size());

  // Kernels write point-major (point p of thread k at p * seeds + k) in cell units; reorder and
  // convert in double precision like the CPU path.
  const auto cellPositions = vk::readBackAs<glm::vec3>(ctx, outputs.positions);
  const auto chunkTimes = vk::readBackAs<float>(ctx, outputs.times);
  const auto chunkVectors = vk::readBackAs<glm::vec3>(ctx, outputs.vectors);
  const auto chunkCounts = vk::readBackAs<std::uint32_t>(ctx, outputs.pointCounts);
  const auto chunkReasons = vk::readBackAs<std::int32_t>(ctx, outputs.reasons);
  const glm::dvec3 origin = volume_->transform.origin, spacing = volume_->transform.spacing;
  tbb::parallel_for(std::size_t(0), seeds.size(), [&](std::size_t k) {
    const std::uint32_t seed = firstSeed + order[k];
    out.steps[seed] = chunkCounts[k] - 1;
    out.pointCounts[seed] = params.keepHistory ? chunkCounts[k] : 1;
    out.reasons[seed] = chunkReasons[k];
    for (std::uint32_t p = 0; p < out.pointCounts[seed]; ++p) {
      const std::size_t from = p * seeds.size() + k, to = out.at(seed, p);
      out.positions[to] = glm::vec3(origin + spacing * glm::dvec3(cellPositions[from]));
      out.times[to] = chunkTimes[from];
      out.vectors[to] = chunkVectors[from];
    }
  });
}

}  // namespace amrstream::gpu
