#include "vk/acceleration_structure.hpp"

#include <algorithm>
#include <utility>

#include "vk/context.hpp"
#include "vk/debug_names.hpp"
#include "vk/vk_error.hpp"

namespace amrstream::vk {

AccelerationStructure::AccelerationStructure(const Context& ctx,
                                             VkAccelerationStructureTypeKHR type, VkDeviceSize size,
                                             std::string_view name)
    : buffer_(Buffer::deviceLocal(ctx, size,
                                  VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                                      VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                  name)),
      type_(type) {
  const DeviceFunctions& f = ctx.functions();
  // Offset 0 of a buffer of its own meets the rule that the offset be a multiple of 256.
  VkAccelerationStructureCreateInfoKHR info{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
  info.buffer = buffer_.handle();
  info.offset = 0;
  info.size = size;
  info.type = type;
  VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
  AMRSTREAM_VK_CHECK(f.vkCreateAccelerationStructureKHR(ctx.device(), &info, nullptr, &handle));
  handle_ = UniqueHandle<VkAccelerationStructureKHR>(
      {ctx.device(), f.vkDestroyAccelerationStructureKHR.get()}, handle);
  setDebugName(ctx, handle, name);

  VkAccelerationStructureDeviceAddressInfoKHR addressInfo{
      VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
  addressInfo.accelerationStructure = handle;
  address_ = f.vkGetAccelerationStructureDeviceAddressKHR(ctx.device(), &addressInfo);
}

AccelerationStructure::AccelerationStructure(AccelerationStructure&& other) noexcept
    : buffer_(std::move(other.buffer_)),
      handle_(std::move(other.handle_)),
      type_(other.type_),
      address_(std::exchange(other.address_, 0)) {}

AccelerationStructure& AccelerationStructure::operator=(AccelerationStructure&& other) noexcept {
  if (this != &other) {
    handle_.reset();  // before the buffer it lives in
    buffer_ = std::move(other.buffer_);
    handle_ = std::move(other.handle_);
    type_ = other.type_;
    address_ = std::exchange(other.address_, 0);
  }
  return *this;
}

ScratchBuffer::ScratchBuffer(const Context& ctx, VkDeviceSize size, std::string_view name) {
  // The buffer's own alignment need not meet the scratch alignment, so over-allocate and round
  // the address up.
  const VkDeviceSize alignment = std::max<VkDeviceSize>(
      1, ctx.accelerationStructureProperties().minAccelerationStructureScratchOffsetAlignment);
  buffer_ = Buffer::deviceLocal(
      ctx, size + alignment - 1,
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, name);
  address_ = (buffer_.deviceAddress() + alignment - 1) / alignment * alignment;
  size_ = size;
}

}  // namespace amrstream::vk
