#pragma once
// DescriptorWrites: the targets of one descriptor set's bindings, each given by its binding index
// (the names in shaders/glsl/shared/*_bindings.h, which the kernels' layout(binding = ...) use
// too), then written to the set at once. Each binding is one descriptor: a whole buffer or an
// acceleration structure. A binding left without a target is an error, not an unset descriptor.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vk/buffer.hpp"

namespace amrstream::vk {

class Context;

// What one binding points at: a whole buffer, or an acceleration structure.
struct DescriptorTarget {
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkAccelerationStructureKHR structure = VK_NULL_HANDLE;
};

inline DescriptorTarget storageTarget(const Buffer& buffer) {
  return {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffer.handle()};
}

inline DescriptorTarget uniformTarget(const Buffer& buffer) {
  return {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, buffer.handle()};
}

inline DescriptorTarget structureTarget(VkAccelerationStructureKHR structure) {
  return {VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR, VK_NULL_HANDLE, structure};
}

class DescriptorWrites {
 public:
  // A set of `bindingCount` bindings (an AMRSTREAM_*_BINDING_COUNT); `setName` names it in errors.
  DescriptorWrites(std::string_view setName, std::uint32_t bindingCount);

  // Throws std::logic_error for a binding past the count, or one given a target before.
  DescriptorWrites& set(std::uint32_t binding, const DescriptorTarget& target);
  // The whole of `buffer` as a storage buffer.
  DescriptorWrites& set(std::uint32_t binding, const Buffer& buffer) {
    return set(binding, storageTarget(buffer));
  }

  // Points every binding of `set` at its target. Throws std::logic_error, writing nothing, when a
  // binding has none.
  void write(const Context& ctx, VkDescriptorSet set) const;

 private:
  void requireEveryTarget() const;

  std::string setName_;
  std::vector<std::optional<DescriptorTarget>> targets_;
};

}  // namespace amrstream::vk
