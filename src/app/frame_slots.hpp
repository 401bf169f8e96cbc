#pragma once
// FrameSlots: what each frame in flight needs while the device works on it: a primary command
// buffer, a fence that signals when the device has finished the frame (created signalled, so the
// first wait returns at once) and the semaphore the swapchain signals when the frame's image may
// be written. Owns the command pool they come from; the context must outlive it.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::app {

struct FrameSlot {
  vk::UniqueHandle<VkCommandBuffer> commands;
  vk::UniqueHandle<VkFence> finished;
  vk::UniqueHandle<VkSemaphore> imageAcquired;
};

class FrameSlots {
 public:
  FrameSlots(const vk::Context& ctx, uint32_t count);

  FrameSlot& operator[](uint32_t index) { return slots_[index]; }
  uint32_t size() const { return static_cast<uint32_t>(slots_.size()); }

 private:
  vk::UniqueHandle<VkCommandPool> pool_;
  std::vector<FrameSlot> slots_;
};

vk::UniqueHandle<VkSemaphore> createSemaphore(const vk::Context& ctx);

}  // namespace amrstream::app
