#include "vk/descriptor_writes.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "vk/context.hpp"

namespace amrstream::vk {

namespace {

// The write of one binding, pointing into `buffer` or `structure` (which must outlive it).
VkWriteDescriptorSet bindingWrite(VkDescriptorSet set, std::uint32_t binding,
                                  const DescriptorTarget& target, VkDescriptorBufferInfo& buffer,
                                  VkWriteDescriptorSetAccelerationStructureKHR& structure) {
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = target.type;
  if (target.type == VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR) {
    structure = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
    structure.accelerationStructureCount = 1;
    structure.pAccelerationStructures = &target.structure;
    write.pNext = &structure;
  } else {
    buffer = {target.buffer, 0, VK_WHOLE_SIZE};
    write.pBufferInfo = &buffer;
  }
  return write;
}

}  // namespace

DescriptorWrites::DescriptorWrites(std::string_view setName, std::uint32_t bindingCount)
    : setName_(setName), targets_(bindingCount) {}

DescriptorWrites& DescriptorWrites::set(std::uint32_t binding, const DescriptorTarget& target) {
  if (binding >= targets_.size())
    throw std::logic_error(fmt::format("DescriptorWrites: the {} set has no binding {} (it has {})",
                                       setName_, binding, targets_.size()));
  if (targets_[binding])
    throw std::logic_error(fmt::format(
        "DescriptorWrites: binding {} of the {} set is given a target twice", binding, setName_));
  targets_[binding] = target;
  return *this;
}

void DescriptorWrites::requireEveryTarget() const {
  for (std::size_t binding = 0; binding < targets_.size(); ++binding)
    if (!targets_[binding])
      throw std::logic_error(fmt::format("DescriptorWrites: binding {} of the {} set has no target",
                                         binding, setName_));
}

void DescriptorWrites::write(const Context& ctx, VkDescriptorSet set) const {
  requireEveryTarget();
  const std::size_t count = targets_.size();
  std::vector<VkDescriptorBufferInfo> buffers(count);
  std::vector<VkWriteDescriptorSetAccelerationStructureKHR> structures(count);
  std::vector<VkWriteDescriptorSet> writes(count);
  for (std::size_t binding = 0; binding < count; ++binding)
    writes[binding] = bindingWrite(set, static_cast<std::uint32_t>(binding), *targets_[binding],
                                   buffers[binding], structures[binding]);
  vkUpdateDescriptorSets(ctx.device(), static_cast<std::uint32_t>(count), writes.data(), 0,
                         nullptr);
}

}  // namespace amrstream::vk
