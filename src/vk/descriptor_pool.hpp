#pragma once
// DescriptorPool: a pool that hands out descriptor sets and frees them all at once (reset()), plus
// writeDescriptors(), which points binding i of a set at targets[i]. For kernels whose bindings
// are all buffers or acceleration structures, each binding one descriptor.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "vk/buffer.hpp"
#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

class DescriptorPool {
 public:
  // Room for `maxSets` sets, each with up to `perSet` descriptors of each type listed.
  DescriptorPool(const Context& ctx, std::uint32_t maxSets,
                 std::span<const VkDescriptorPoolSize> perSet);

  VkDescriptorSet allocate(VkDescriptorSetLayout layout);
  // Returns every set to the pool; none may still be in use by the device.
  void reset();

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  UniqueHandle<VkDescriptorPool> pool_;
};

// What one binding points at: a whole buffer, or an acceleration structure.
struct DescriptorTarget {
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkAccelerationStructureKHR structure = VK_NULL_HANDLE;
};

// A storage buffer binding's target: the whole of `buffer`.
inline DescriptorTarget storageTarget(const Buffer& buffer) {
  return {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffer.handle()};
}

// Binding i of `set` := targets[i].
void writeDescriptors(const Context& ctx, VkDescriptorSet set,
                      std::span<const DescriptorTarget> targets);

}  // namespace amrstream::vk
