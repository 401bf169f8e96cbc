#pragma once
// Swapchain: the images presented to the context's surface, and a view of each. Its images can
// be blitted to, read back (screenshots) and drawn on (the overlay), so it asks for
// TRANSFER_DST, TRANSFER_SRC and COLOR_ATTACHMENT usage and an 8-bit RGBA or BGRA format, UNORM
// preferred (the frame's bytes and Dear ImGui's colours are display-ready). The format is chosen
// once and kept through recreate(), so render passes made for it stay valid. Owns the swapchain
// and the views; the context must outlive it. Move-only.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::app {

// FIFO waits for the display (no tearing, never drops frames); MAILBOX replaces the queued frame
// (no tearing, lowest latency); IMMEDIATE does not wait (may tear). FIFO is the fallback, since
// every device supports it.
enum class PresentMode { Fifo, Mailbox, Immediate };

class Swapchain {
 public:
  // `extent` is the window's framebuffer size, used where the surface leaves the size to the
  // application. Throws ContextError when the surface offers no usable format or usage or has no
  // area, VulkanError when a Vulkan call fails.
  Swapchain(const vk::Context& ctx, VkExtent2D extent, PresentMode preferred);

  // A new swapchain for the surface's current size, made from the old one. Waits until the device
  // is idle first: the old images and views may still be in use. Returns false, keeping the old
  // swapchain, while the surface has no area (a minimised window).
  bool recreate(VkExtent2D extent);

  VkSwapchainKHR handle() const { return swapchain_.get(); }
  VkFormat format() const { return format_.format; }
  VkExtent2D extent() const { return extent_; }
  VkPresentModeKHR presentMode() const { return presentMode_; }
  uint32_t imageCount() const { return static_cast<uint32_t>(images_.size()); }
  VkImage image(uint32_t index) const { return images_[index]; }
  VkImageView view(uint32_t index) const { return views_[index].get(); }

 private:
  bool create(VkExtent2D extent);

  const vk::Context* ctx_;
  VkSurfaceFormatKHR format_{};
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkExtent2D extent_{};
  vk::UniqueHandle<VkSwapchainKHR> swapchain_;
  std::vector<VkImage> images_;  // owned by the swapchain
  std::vector<vk::UniqueHandle<VkImageView>> views_;
};

}  // namespace amrstream::app
