#pragma once
// AccelerationStructure: one VkAccelerationStructureKHR and the device-local buffer it lives in
// (created first, destroyed last), with its device address cached. Move-only; contents are
// undefined until a build or copy writes them. The context must outlive it.
//
// ScratchBuffer: build scratch memory whose device address is aligned to
// minAccelerationStructureScratchOffsetAlignment.

#include <vulkan/vulkan.h>

#include <string_view>

#include "vk/buffer.hpp"
#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

class AccelerationStructure {
 public:
  AccelerationStructure() = default;
  AccelerationStructure(const Context& ctx, VkAccelerationStructureTypeKHR type, VkDeviceSize size,
                        std::string_view name);
  AccelerationStructure(AccelerationStructure&& other) noexcept;
  AccelerationStructure& operator=(AccelerationStructure&& other) noexcept;

  VkAccelerationStructureKHR handle() const { return handle_.get(); }
  VkAccelerationStructureTypeKHR type() const { return type_; }
  // What instances and shaders refer to (VkAccelerationStructureInstanceKHR's
  // accelerationStructureReference).
  VkDeviceAddress deviceAddress() const { return address_; }
  VkDeviceSize size() const { return buffer_.size(); }
  const Buffer& buffer() const { return buffer_; }

 private:
  Buffer buffer_;
  UniqueHandle<VkAccelerationStructureKHR> handle_;
  VkAccelerationStructureTypeKHR type_ = VK_ACCELERATION_STRUCTURE_TYPE_GENERIC_KHR;
  VkDeviceAddress address_ = 0;
};

class ScratchBuffer {
 public:
  ScratchBuffer(const Context& ctx, VkDeviceSize size, std::string_view name);
  // Aligned for VkAccelerationStructureBuildGeometryInfoKHR::scratchData.
  VkDeviceAddress deviceAddress() const { return address_; }
  VkBuffer handle() const { return buffer_.handle(); }
  VkDeviceSize size() const { return size_; }  // usable bytes from deviceAddress()

 private:
  Buffer buffer_;
  VkDeviceAddress address_ = 0;
  VkDeviceSize size_ = 0;
};

}  // namespace amrstream::vk
