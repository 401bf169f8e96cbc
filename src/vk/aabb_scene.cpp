// buildTlas and buildAabbScene (declared in aabb_scene.hpp).
#include "vk/aabb_scene.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "vk/buffer_transfer.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {
namespace {

VkAccelerationStructureInstanceKHR instanceOf(const AabbBlas& blas) {
  VkAccelerationStructureInstanceKHR instance{};
  // Row-major 3x4 identity: the boxes are already in world coordinates.
  instance.transform.matrix[0][0] = 1.0f;
  instance.transform.matrix[1][1] = 1.0f;
  instance.transform.matrix[2][2] = 1.0f;
  instance.instanceCustomIndex = blas.firstBox;
  instance.mask = 0xFF;
  instance.instanceShaderBindingTableRecordOffset = 0;
  instance.flags = 0;
  instance.accelerationStructureReference = blas.structure.deviceAddress();
  return instance;
}

}  // namespace

AccelerationStructure buildTlas(const Context& ctx, std::span<const AabbBlas> blases,
                                std::string_view name) {
  if (!ctx.has(Capability::AccelerationStructure)) {
    throw VulkanError(VK_ERROR_EXTENSION_NOT_PRESENT,
                      "buildTlas needs a context built with Capability::AccelerationStructure");
  }
  if (blases.size() > ctx.accelerationStructureProperties().maxInstanceCount) {
    throw std::length_error(fmt::format("'{}': {} instances exceed maxInstanceCount {}", name,
                                        blases.size(),
                                        ctx.accelerationStructureProperties().maxInstanceCount));
  }
  std::vector<VkAccelerationStructureInstanceKHR> instances;
  for (const AabbBlas& blas : blases) {
    if (blas.firstBox > 0xFFFFFF) {
      throw std::length_error(fmt::format(
          "'{}': first box {} does not fit the 24-bit instanceCustomIndex", name, blas.firstBox));
    }
    instances.push_back(instanceOf(blas));
  }
  // Instance data must be 16-byte aligned; buffer memory alignment is at least that in practice,
  // and a buffer of its own starts at offset 0.
  const Buffer instanceBuffer =
      uploadToDeviceLocal(ctx, instances,
                          VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
                              VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                          fmt::format("{} instances", name));
  if (instanceBuffer.deviceAddress() % 16 != 0) {
    throw std::logic_error("buildTlas: instance buffer address is not 16-byte aligned");
  }

  VkAccelerationStructureGeometryKHR geometry{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
  geometry.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
  geometry.geometry.instances.sType =
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
  geometry.geometry.instances.arrayOfPointers = VK_FALSE;
  geometry.geometry.instances.data.deviceAddress = instanceBuffer.deviceAddress();

  VkAccelerationStructureBuildGeometryInfoKHR build{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
  build.type = VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR;
  build.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
  build.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
  build.geometryCount = 1;
  build.pGeometries = &geometry;

  const auto count = static_cast<uint32_t>(instances.size());
  VkAccelerationStructureBuildSizesInfoKHR sizes{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
  ctx.functions().vkGetAccelerationStructureBuildSizesKHR(
      ctx.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &build, &count, &sizes);
  AccelerationStructure tlas(ctx, build.type, sizes.accelerationStructureSize,
                             fmt::format("{} TLAS", name));
  const ScratchBuffer scratch(ctx, sizes.buildScratchSize, fmt::format("{} TLAS scratch", name));
  build.dstAccelerationStructure = tlas.handle();
  build.scratchData.deviceAddress = scratch.deviceAddress();

  submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    // BLAS builds and compaction copies (AS write) before this build reads them (AS read).
    memoryBarrier(cmd, access::kAccelerationStructureWrite, access::kAccelerationStructureRead);
    const VkAccelerationStructureBuildRangeInfoKHR range{count, 0, 0, 0};
    const VkAccelerationStructureBuildRangeInfoKHR* rangePointer = &range;
    ctx.functions().vkCmdBuildAccelerationStructuresKHR(cmd, 1, &build, &rangePointer);
    // Traversal in later submissions (ray queries, ray tracing shaders) reads the TLAS.
    memoryBarrier(cmd, access::kAccelerationStructureWrite, access::kAny);
  });
  return tlas;
}

AabbScene buildAabbScene(const Context& ctx, std::span<const VkAabbPositionsKHR> boxes,
                         std::string_view name, uint32_t maxPrimitivesOverride) {
  AabbScene scene;
  scene.blases = buildAabbBlas(ctx, boxes, name, maxPrimitivesOverride);
  scene.tlas = buildTlas(ctx, scene.blases, name);
  scene.boxCount = static_cast<uint32_t>(boxes.size());
  return scene;
}

}  // namespace amrstream::vk
