#pragma once
// Buffer: one VkBuffer and the VkDeviceMemory bound to it (one allocation per buffer; fine for
// the few large arrays a trace needs). Created by intent:
//   deviceLocal  fastest for the device, not host-visible
//   upload       host-visible and coherent, persistently mapped: the host writes, the device reads
//   readback     host-visible, host-cached where possible, persistently mapped: the device writes
// A buffer whose usage has SHADER_DEVICE_ADDRESS_BIT gets its memory with the device-address
// flag and caches its address. Move-only; the context must outlive it.
//
// Size 0 is allowed (empty arrays are common): Vulkan forbids zero-size buffers, so a 16-byte
// buffer is created, size() reports 0 and mapped() is empty.

#include <vulkan/vulkan.h>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include "vk/memory_ledger.hpp"
#include "vk/unique_handle.hpp"

namespace amrstream::vk {

class Context;

class Buffer {
 public:
  enum class Intent { DeviceLocal, Upload, Readback };

  // All three throw VulkanError naming the buffer and its size when creation or allocation fails
  // ("out of device memory allocating 'positions' (12.3 GiB): ...").
  static Buffer deviceLocal(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                            std::string_view name);
  static Buffer upload(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                       std::string_view name);
  static Buffer readback(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage,
                         std::string_view name);

  Buffer() = default;
  // Moves leave the source empty (no handle, no mapping, size 0).
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;

  VkBuffer handle() const { return buffer_.get(); }
  // The size asked for (0 for an empty buffer).
  VkDeviceSize size() const { return size_; }
  VkBufferUsageFlags usage() const { return usage_; }
  const std::string& name() const { return name_; }
  // 0 unless the usage has VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT.
  VkDeviceAddress deviceAddress() const { return address_; }

  bool isMapped() const { return mapped_ != nullptr; }
  // The mapped bytes of an upload or readback buffer; empty for device-local ones.
  std::span<std::byte> mapped() { return {mapped_, mapped_ ? size_ : 0}; }
  std::span<const std::byte> mapped() const { return {mapped_, mapped_ ? size_ : 0}; }
  // Makes device writes visible to mapped() reads (after the device's work has completed and a
  // barrier to HOST_READ). Needed only for non-coherent memory; a no-op otherwise.
  void invalidateMapped() const;

 private:
  Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, std::string_view name,
         Intent intent);

  std::string name_;
  VkDeviceSize size_ = 0;
  VkBufferUsageFlags usage_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  bool coherent_ = true;
  // Destroyed in reverse: the memory is freed (and implicitly unmapped) before the buffer is
  // destroyed, which the specification allows as long as the buffer is not used in between.
  UniqueHandle<VkBuffer> buffer_;
  MemoryCharge charge_;  // released after the memory is freed
  UniqueHandle<VkDeviceMemory> memory_;
  std::byte* mapped_ = nullptr;
  VkDeviceAddress address_ = 0;
};

}  // namespace amrstream::vk
