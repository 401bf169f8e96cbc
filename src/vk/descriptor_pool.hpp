#pragma once
// DescriptorPool: a pool that hands out descriptor sets and frees them all at once (reset()). Their
// bindings are written through DescriptorWrites (vk/descriptor_writes.hpp).

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

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

}  // namespace amrstream::vk
