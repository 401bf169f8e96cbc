// buildAabbBlas: split, build, compact (declared in aabb_scene.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "vk/aabb_scene.hpp"
#include "vk/buffer_transfer.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {
namespace {

constexpr uint64_t kMaxCustomIndex = 0xFFFFFF;  // instanceCustomIndex is a 24-bit field

void requireAccelerationStructures(const Context& ctx, std::string_view what) {
  if (!ctx.has(Capability::AccelerationStructure)) {
    throw VulkanError(VK_ERROR_EXTENSION_NOT_PRESENT,
                      fmt::format("{} needs a context built with "
                                  "Capability::AccelerationStructure",
                                  what));
  }
}

struct Range {
  uint32_t first = 0;
  uint32_t count = 0;
};

std::vector<Range> splitBoxes(uint64_t total, uint32_t limit) {
  std::vector<Range> ranges;
  for (uint64_t first = 0; first < total; first += limit) {
    ranges.push_back({static_cast<uint32_t>(first),
                      static_cast<uint32_t>(std::min<uint64_t>(limit, total - first))});
  }
  return ranges;
}

UniqueHandle<VkQueryPool> compactedSizeQueries(const Context& ctx, uint32_t count) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR;
  info.queryCount = count;
  VkQueryPool pool = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(vkCreateQueryPool(ctx.device(), &info, nullptr, &pool));
  return UniqueHandle<VkQueryPool>(ctx.device(), pool);
}

}  // namespace

uint32_t maxBoxesPerBlas(const Context& ctx, uint32_t override) {
  const auto limit = static_cast<uint32_t>(
      std::min<uint64_t>(ctx.accelerationStructureProperties().maxPrimitiveCount, UINT32_MAX));
  return override != 0 ? std::min(limit, override) : limit;
}

uint64_t maxBoxesPerScene(const Context& ctx, uint32_t override) {
  return kMaxCustomIndex + maxBoxesPerBlas(ctx, override);
}

namespace {

void requireBoxesFit(const Context& ctx, std::size_t boxes, std::string_view name,
                     uint32_t maxPrimitivesOverride) {
  const uint32_t limit = maxBoxesPerBlas(ctx, maxPrimitivesOverride);
  if (limit == 0) throw std::logic_error("buildAabbBlas: maxPrimitiveCount is 0");
  if (boxes > maxBoxesPerScene(ctx, maxPrimitivesOverride)) {
    throw std::length_error(fmt::format(
        "'{}': {} boxes are more than one TLAS can address with 24-bit instance custom indices "
        "and {} boxes per BLAS ({} at most)",
        name, boxes, limit, maxBoxesPerScene(ctx, maxPrimitivesOverride)));
  }
}

// The buffer the builds read the boxes from: `own`, or with `reuse` one of its buffers. A few
// boxes are read by the build straight from host-visible memory: no copy, no wait.
const Buffer& boxInput(const Context& ctx, std::span<const VkAabbPositionsKHR> boxes,
                       std::string_view name, BlasBuildBuffers* reuse, Buffer& own) {
  constexpr VkBufferUsageFlags kInput =
      VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
      VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  constexpr std::size_t kHostReadBoxes = std::size_t(1) << 16;
  if (boxes.size() <= kHostReadBoxes) {
    Buffer& host = reuse ? reuse->hostBoxes : own;
    if (host.size() < boxes.size_bytes())
      host = Buffer::upload(ctx, reuse ? 2 * boxes.size_bytes() : boxes.size_bytes(), kInput,
                            fmt::format("{} boxes", name));
    std::memcpy(host.mapped().data(), boxes.data(), boxes.size_bytes());
    return host;
  }
  Buffer device = uploadToDeviceLocal(ctx, boxes, kInput, fmt::format("{} boxes", name));
  if (!reuse) return own = std::move(device);
  return reuse->deviceBoxes = std::move(device);  // kept until the recorded builds have run
}

// One geometry per BLAS, each reading its slice of the one box array (the slice address stays a
// multiple of 8 bytes, as AABB data requires; a 32-bit primitiveOffset could overflow).
struct BlasBuild {
  VkAccelerationStructureGeometryKHR geometry{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  VkAccelerationStructureBuildGeometryInfoKHR info{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};

  BlasBuild(VkDeviceAddress boxes, bool compact) {
    geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
    geometry.geometry.aabbs.sType =
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
    geometry.geometry.aabbs.data.deviceAddress = boxes;
    geometry.geometry.aabbs.stride = sizeof(VkAabbPositionsKHR);
    geometry.flags = VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR;
    info.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
    info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
                 (compact ? VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR : 0);
    info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    info.geometryCount = 1;
    info.pGeometries = &geometry;
  }
  BlasBuild(const BlasBuild&) = delete;  // info points at geometry
  BlasBuild& operator=(const BlasBuild&) = delete;
};

// The BLASes, sized for their slices; `scratchSize` is the largest build's scratch.
std::vector<AabbBlas> createBlases(const Context& ctx, const BlasBuild& build,
                                   const std::vector<Range>& ranges, std::string_view name,
                                   VkDeviceSize& scratchSize) {
  std::vector<AabbBlas> blases;
  scratchSize = 0;
  for (size_t i = 0; i < ranges.size(); ++i) {
    VkAccelerationStructureBuildSizesInfoKHR sizes{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    ctx.functions().vkGetAccelerationStructureBuildSizesKHR(
        ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &build.info,
        &ranges[i].count, &sizes);
    blases.push_back({AccelerationStructure(ctx, build.info.type, sizes.accelerationStructureSize,
                                            fmt::format("{} BLAS {}", name, i)),
                      ranges[i].first, ranges[i].count, sizes.accelerationStructureSize});
    scratchSize = std::max(scratchSize, sizes.buildScratchSize);
  }
  return blases;
}

// Replaces each BLAS by a compacted copy where that is smaller.
void compactBlases(const Context& ctx, std::vector<AabbBlas>& blases, VkQueryPool queries,
                   std::string_view name) {
  const DeviceFunctions& f = ctx.functions();
  const auto count = static_cast<uint32_t>(blases.size());
  std::vector<VkDeviceSize> compactedSizes(count);
  AMRSTREAM_VK_CHECK(vkGetQueryPoolResults(ctx.device(), queries, 0, count,
                                           compactedSizes.size() * sizeof(VkDeviceSize),
                                           compactedSizes.data(), sizeof(VkDeviceSize),
                                           VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  std::vector<AccelerationStructure> compacted(count);
  for (uint32_t i = 0; i < count; ++i) {
    if (compactedSizes[i] > 0 && compactedSizes[i] < blases[i].buildSize) {
      compacted[i] = AccelerationStructure(ctx, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                                           compactedSizes[i], fmt::format("{} BLAS {}", name, i));
    }
  }
  submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    for (uint32_t i = 0; i < count; ++i) {
      if (compacted[i].handle() == VK_NULL_HANDLE) continue;
      VkCopyAccelerationStructureInfoKHR copy{
          VK_STRUCTURE_TYPE_COPY_ACCELERATION_STRUCTURE_INFO_KHR};
      copy.src = blases[i].structure.handle();
      copy.dst = compacted[i].handle();
      copy.mode = VK_COPY_ACCELERATION_STRUCTURE_MODE_COMPACT_KHR;
      f.vkCmdCopyAccelerationStructureKHR(cmd, &copy);
    }
    // Later submissions (the TLAS build) read these BLASes.
    memoryBarrier(cmd, access::kAccelerationStructureWrite, access::kAny);
  });
  for (uint32_t i = 0; i < count; ++i) {
    if (compacted[i].handle() != VK_NULL_HANDLE) blases[i].structure = std::move(compacted[i]);
  }
}

// buildAabbBlas (no `reuse`, no `into`), or recordAabbBlas (both, no compaction).
std::vector<AabbBlas> makeAabbBlas(const Context& ctx, std::span<const VkAabbPositionsKHR> boxes,
                                   std::string_view name, uint32_t maxPrimitivesOverride,
                                   bool compact, BlasBuildBuffers* reuse, VkCommandBuffer into) {
  requireAccelerationStructures(ctx, "buildAabbBlas");
  requireBoxesFit(ctx, boxes.size(), name, maxPrimitivesOverride);
  if (boxes.empty()) return {};
  Buffer ownBoxes;
  const Buffer& boxBuffer = boxInput(ctx, boxes, name, reuse, ownBoxes);
  BlasBuild build(boxBuffer.deviceAddress(), compact);
  VkDeviceSize scratchSize = 0;
  std::vector<AabbBlas> blases = createBlases(
      ctx, build, splitBoxes(boxes.size(), maxBoxesPerBlas(ctx, maxPrimitivesOverride)), name,
      scratchSize);

  std::optional<ScratchBuffer> ownScratch;
  std::optional<ScratchBuffer>& scratchSlot = reuse ? reuse->scratch : ownScratch;
  if (!scratchSlot || scratchSlot->size() < scratchSize)
    scratchSlot.emplace(ctx, reuse ? 2 * scratchSize : scratchSize,
                        fmt::format("{} BLAS scratch", name));
  const ScratchBuffer& scratch = *scratchSlot;
  const auto count = static_cast<uint32_t>(blases.size());
  const UniqueHandle<VkQueryPool> queries =
      compact ? compactedSizeQueries(ctx, count) : UniqueHandle<VkQueryPool>();
  std::vector<VkAccelerationStructureKHR> handles;
  for (const AabbBlas& blas : blases) handles.push_back(blas.structure.handle());

  const DeviceFunctions& f = ctx.functions();
  const auto recordBuilds = [&](VkCommandBuffer cmd) {
    if (compact) vkCmdResetQueryPool(cmd, queries.get(), 0, count);
    for (size_t i = 0; i < blases.size(); ++i) {
      build.info.dstAccelerationStructure = handles[i];
      build.info.scratchData.deviceAddress = scratch.deviceAddress();
      build.geometry.geometry.aabbs.data.deviceAddress =
          boxBuffer.deviceAddress() + uint64_t{blases[i].firstBox} * sizeof(VkAabbPositionsKHR);
      const VkAccelerationStructureBuildRangeInfoKHR range{blases[i].boxCount, 0, 0, 0};
      const VkAccelerationStructureBuildRangeInfoKHR* rangePointer = &range;
      f.vkCmdBuildAccelerationStructuresKHR(cmd, 1, &build.info, &rangePointer);
      // The builds share one scratch buffer, so each must finish before the next starts; the
      // last one must finish before its compacted size is read.
      memoryBarrier(cmd, access::kAccelerationStructureWrite,
                    {VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                     VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                         VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR});
    }
    if (compact)
      f.vkCmdWriteAccelerationStructuresPropertiesKHR(
          cmd, count, handles.data(), VK_QUERY_TYPE_ACCELERATION_STRUCTURE_COMPACTED_SIZE_KHR,
          queries.get(), 0);
    else  // later commands (the TLAS build) read these BLASes
      memoryBarrier(cmd, access::kAccelerationStructureWrite, access::kAny);
  };
  if (into != VK_NULL_HANDLE) {
    recordBuilds(into);
    return blases;
  }
  submitAndWait(ctx, recordBuilds);
  if (compact) compactBlases(ctx, blases, queries.get(), name);
  return blases;
}

}  // namespace

std::vector<AabbBlas> buildAabbBlas(const Context& ctx, std::span<const VkAabbPositionsKHR> boxes,
                                    std::string_view name, uint32_t maxPrimitivesOverride,
                                    bool compact) {
  return makeAabbBlas(ctx, boxes, name, maxPrimitivesOverride, compact, nullptr, VK_NULL_HANDLE);
}

std::vector<AabbBlas> recordAabbBlas(const Context& ctx, VkCommandBuffer cmd,
                                     std::span<const VkAabbPositionsKHR> boxes,
                                     std::string_view name, BlasBuildBuffers& reuse) {
  return makeAabbBlas(ctx, boxes, name, 0, false, &reuse, cmd);
}

}  // namespace amrstream::vk
