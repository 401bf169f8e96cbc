#include "vk/tlas_builder.hpp"

#include <fmt/format.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "vk/commands.hpp"
#include "vk/context.hpp"

namespace amrstream::vk {

namespace {

VkAccelerationStructureGeometryKHR instanceGeometry(VkDeviceAddress instances) {
  VkAccelerationStructureGeometryKHR geometry{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry.geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geometry.geometry.instances.arrayOfPointers = VK_FALSE;
  geometry.geometry.instances.data.deviceAddress = instances;
  return geometry;
}

VkAccelerationStructureBuildGeometryInfoKHR buildInfo(
    const VkAccelerationStructureGeometryKHR& geometry) {
  VkAccelerationStructureBuildGeometryInfoKHR build{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  build.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  build.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  build.geometryCount = 1;
  build.pGeometries = &geometry;
  return build;
}

VkAccelerationStructureBuildSizesInfoKHR sizesFor(const Context& ctx, std::uint32_t capacity) {
  const VkAccelerationStructureGeometryKHR geometry = instanceGeometry(0);
  const VkAccelerationStructureBuildGeometryInfoKHR build = buildInfo(geometry);
  VkAccelerationStructureBuildSizesInfoKHR sizes{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  ctx.functions().vkGetAccelerationStructureBuildSizesKHR(
      ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &build, &capacity, &sizes);
  return sizes;
}

}  // namespace

TlasBuilder::TlasBuilder(const Context& ctx, std::uint32_t capacity, std::string_view name)
    : ctx_(&ctx),
      capacity_(capacity),
      instances_(
          Buffer::upload(ctx, capacity * sizeof(VkAccelerationStructureInstanceKHR),
                         VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                             VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                         fmt::format("{} instances", name))),
      sizes_(sizesFor(ctx, capacity)),
      tlas_(ctx, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, sizes_.accelerationStructureSize,
            fmt::format("{} TLAS", name)),
      scratch_(ctx, sizes_.buildScratchSize, fmt::format("{} TLAS scratch", name)) {
  if (capacity == 0 || capacity > ctx.accelerationStructureProperties().maxInstanceCount)
    throw std::length_error(fmt::format("TlasBuilder: {} instances", capacity));
  // Instance data must be 16-byte aligned.
  if (instances_.deviceAddress() % 16 != 0)
    throw std::logic_error("TlasBuilder: instance buffer address is not 16-byte aligned");
}

const AccelerationStructure& TlasBuilder::build(std::span<const AabbBlas> blases) {
  submitAndWait(*ctx_, [&](VkCommandBuffer cmd) { record(cmd, blases); });
  return tlas_;
}

void TlasBuilder::record(VkCommandBuffer cmd, std::span<const AabbBlas> blases) {
  if (blases.size() > capacity_)
    throw std::length_error(
        fmt::format("TlasBuilder: {} instances exceed its capacity {}", blases.size(), capacity_));
  std::vector<VkAccelerationStructureInstanceKHR> instances;
  instances.reserve(blases.size());
  for (const AabbBlas& blas : blases) {
    if (blas.firstBox > 0xFFFFFF)
      throw std::length_error(fmt::format(
          "TlasBuilder: first box {} does not fit the 24-bit instanceCustomIndex", blas.firstBox));
    instances.push_back(tlasInstanceOf(blas));
  }
  // Coherent memory, written before the submission: visible to the build.
  if (!instances.empty())
    std::memcpy(instances_.mapped().data(), instances.data(),
                instances.size() * sizeof(VkAccelerationStructureInstanceKHR));
  const VkAccelerationStructureGeometryKHR geometry = instanceGeometry(instances_.deviceAddress());
  VkAccelerationStructureBuildGeometryInfoKHR build = buildInfo(geometry);
  build.dstAccelerationStructure = tlas_.handle();
  build.scratchData.deviceAddress = scratch_.deviceAddress();
  const auto count = static_cast<std::uint32_t>(instances.size());
  // The BLAS builds, and earlier traversals of this TLAS, before this build reads the one and
  // rewrites the other.
  memoryBarrier(cmd, access::kAny,
                {VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                 VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR |
                     VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR});
  const VkAccelerationStructureBuildRangeInfoKHR range{count, 0, 0, 0};
  const VkAccelerationStructureBuildRangeInfoKHR* rangePointer = &range;
  ctx_->functions().vkCmdBuildAccelerationStructuresKHR(cmd, 1, &build, &rangePointer);
  memoryBarrier(cmd, access::kAccelerationStructureWrite, access::kAny);
}

}  // namespace amrstream::vk
