// buildTlas and buildAabbScene (declared in aabb_scene.hpp).
#include "vk/aabb_scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "vk/buffer_transfer.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/tlas_builder.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {
VkAccelerationStructureInstanceKHR tlasInstanceOf(const AabbBlas& blas) {
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
  TlasBuilder builder(ctx, std::max<uint32_t>(1, static_cast<uint32_t>(blases.size())), name);
  builder.build(blases);
  return std::move(builder).takeTlas();
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
