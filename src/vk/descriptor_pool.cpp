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

void writeDescriptors(const Context& ctx, VkDescriptorSet set,
                      std::span<const DescriptorTarget> targets) {
  std::vector<VkDescriptorBufferInfo> buffers(targets.size());
  std::vector<VkWriteDescriptorSetAccelerationStructureKHR> structures(targets.size());
  std::vector<VkWriteDescriptorSet> writes(targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i) {
    VkWriteDescriptorSet& write = writes[i];
    write = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.dstBinding = static_cast<std::uint32_t>(i);
    write.descriptorCount = 1;
    write.descriptorType = targets[i].type;
    if (targets[i].type == VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR) {
      structures[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
      structures[i].accelerationStructureCount = 1;
      structures[i].pAccelerationStructures = &targets[i].structure;
      write.pNext = &structures[i];
    } else {
      buffers[i] = {targets[i].buffer, 0, VK_WHOLE_SIZE};
      write.pBufferInfo = &buffers[i];
    }
  }
  vkUpdateDescriptorSets(ctx.device(), static_cast<std::uint32_t>(writes.size()), writes.data(), 0,
                         nullptr);
}

}  // namespace amrstream::vk
