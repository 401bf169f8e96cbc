#include "vk/descriptor_pool.hpp"

#include <vector>

#include "vk/context.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {

DescriptorPool::DescriptorPool(const Context& ctx, std::uint32_t maxSets,
                               std::span<const VkDescriptorPoolSize> perSet)
    : device_(ctx.device()) {
  std::vector<VkDescriptorPoolSize> sizes(perSet.begin(), perSet.end());
  for (VkDescriptorPoolSize& size : sizes) size.descriptorCount *= maxSets;
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = maxSets;
  info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  info.pPoolSizes = sizes.data();
  VkDescriptorPool pool;
  AMRSTREAM_VK_CHECK(vkCreateDescriptorPool(device_, &info, nullptr, &pool));
  pool_ = {device_, pool};
}

VkDescriptorSet DescriptorPool::allocate(VkDescriptorSetLayout layout) {
  VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  info.descriptorPool = pool_.get();
  info.descriptorSetCount = 1;
  info.pSetLayouts = &layout;
  VkDescriptorSet set;
  AMRSTREAM_VK_CHECK(vkAllocateDescriptorSets(device_, &info, &set));
  return set;
}

void DescriptorPool::reset() { AMRSTREAM_VK_CHECK(vkResetDescriptorPool(device_, pool_.get(), 0)); }

}  // namespace amrstream::vk
