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

// buildAabbBlas (no `reuse`, no `into`), or recordAabbBlas (both, no compaction).
std::vector<AabbBlas> makeAabbBlas(const Context& ctx, std::span<const VkAabbPositionsKHR> boxes,
                                   std::string_view name, uint32_t maxPrimitivesOverride,
                                   bool compact, BlasBuildBuffers* reuse, VkCommandBuffer into) {
  requireAccelerationStructures(ctx, "buildAabbBlas");
  const DeviceFunctions& f = ctx.functions();
  const uint32_t limit = maxBoxesPerBlas(ctx, maxPrimitivesOverride);
  if (limit == 0) throw std::logic_error("buildAabbBlas: maxPrimitiveCount is 0");
  if (boxes.size() > maxBoxesPerScene(ctx, maxPrimitivesOverride)) {
    throw std::length_error(fmt::format(
        "'{}': {} boxes are more than one TLAS can address with 24-bit instance custom indices "
        "and {} boxes per BLAS ({} at most)",
        name, boxes.size(), limit, maxBoxesPerScene(ctx, maxPrimitivesOverride)));
  }
  if (boxes.empty()) return {};

  // A few boxes are read by the build straight from host-visible memory: no copy, no wait.
  constexpr VkBufferUsageFlags kInput =
      VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
      VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
  constexpr std::size_t kHostReadBoxes = std::size_t(1) << 16;
  Buffer ownBoxes;
  Buffer* hostBoxes = reuse ? &reuse->hostBoxes : &ownBoxes;
  if (boxes.size() <= kHostReadBoxes) {
    if (hostBoxes->size() < boxes.size_bytes())
      *hostBoxes = Buffer::upload(ctx, reuse ? 2 * boxes.size_bytes() : boxes.size_bytes(), kInput,
                                  fmt::format("{} boxes", name));
    std::memcpy(hostBoxes->mapped().data(), boxes.data(), boxes.size_bytes());
  } else {
    ownBoxes = uploadToDeviceLocal(ctx, boxes, kInput, fmt::format("{} boxes", name));
    hostBoxes = &ownBoxes;
    if (reuse) {  // kept until the recorded builds have run
      reuse->deviceBoxes = std::move(ownBoxes);
      hostBoxes = &reuse->deviceBoxes;
    }
  }
  const Buffer& boxBuffer = *hostBoxes;

  // One geometry per BLAS, each reading its slice of the one box array (the slice address stays
  // a multiple of 8 bytes, as AABB data requires; a 32-bit primitiveOffset could overflow).
  VkAccelerationStructureGeometryKHR geometry{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_AABBS_KHR;
  geometry.geometry.aabbs.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR;
  geometry.geometry.aabbs.data.deviceAddress = boxBuffer.deviceAddress();
  geometry.geometry.aabbs.stride = sizeof(VkAabbPositionsKHR);
  geometry.flags = VK_GEOMETRY_NO_DUPLICATE_ANY_HIT_INVOCATION_BIT_KHR;

  VkAccelerationStructureBuildGeometryInfoKHR build{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  build.type = VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR;
  build.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR |
                (compact ? VK_BUILD_ACCELERATION_STRUCTURE_ALLOW_COMPACTION_BIT_KHR : 0);
  build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  build.geometryCount = 1;
  build.pGeometries = &geometry;

  const std::vector<Range> ranges = splitBoxes(boxes.size(), limit);
  std::vector<AabbBlas> blases;
  VkDeviceSize scratchSize = 0;
  for (size_t i = 0; i < ranges.size(); ++i) {
    VkAccelerationStructureBuildSizesInfoKHR sizes{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    f.vkGetAccelerationStructureBuildSizesKHR(ctx.device(),
                                              VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR,
                                              &build, &ranges[i].count, &sizes);
    blases.push_back({AccelerationStructure(ctx, build.type, sizes.accelerationStructureSize,
                                            fmt::format("{} BLAS {}", name, i)),
                      ranges[i].first, ranges[i].count, sizes.accelerationStructureSize});
    scratchSize = std::max(scratchSize, sizes.buildScratchSize);
  }

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

  const auto recordBuilds = [&](VkCommandBuffer cmd) {
    if (compact) vkCmdResetQueryPool(cmd, queries.get(), 0, count);
    for (size_t i = 0; i < blases.size(); ++i) {
      build.dstAccelerationStructure = handles[i];
      build.scratchData.deviceAddress = scratch.deviceAddress();
      geometry.geometry.aabbs.data.deviceAddress =
          boxBuffer.deviceAddress() + uint64_t{blases[i].firstBox} * sizeof(VkAabbPositionsKHR);
      const VkAccelerationStructureBuildRangeInfoKHR range{blases[i].boxCount, 0, 0, 0};
      const VkAccelerationStructureBuildRangeInfoKHR* rangePointer = &range;
      f.vkCmdBuildAccelerationStructuresKHR(cmd, 1, &build, &rangePointer);
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
  if (!compact) return blases;

  std::vector<VkDeviceSize> compactedSizes(count);
  AMRSTREAM_VK_CHECK(vkGetQueryPoolResults(ctx.device(), queries.get(), 0, count,
                                           compactedSizes.size() * sizeof(VkDeviceSize),
                                           compactedSizes.data(), sizeof(VkDeviceSize),
                                           VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));

  std::vector<AccelerationStructure> compacted(count);
  for (uint32_t i = 0; i < count; ++i) {
    if (compactedSizes[i] > 0 && compactedSizes[i] < blases[i].buildSize) {
      compacted[i] = AccelerationStructure(ctx, build.type, compactedSizes[i],
                                           fmt::format("{} BLAS {}", name, i));
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
