#pragma once
// RgbaImage: a device-local 2D image of 8-bit RGBA texels, optimally tiled, that can be copied to
// and blitted from: the renderer's buffer is copied into it so that vkCmdBlitImage can scale it
// and convert it to the swapchain's format. The SRGB variant serves sRGB swapchains, so that the
// bytes pass through the blit unchanged. Owns the image and its memory; the context must outlive
// it. Move-only.

#include <vulkan/vulkan.h>

#include <string_view>

#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::app {

class RgbaImage {
 public:
  RgbaImage() = default;
  // `format` is VK_FORMAT_R8G8B8A8_UNORM or VK_FORMAT_R8G8B8A8_SRGB. Throws VulkanError.
  RgbaImage(const vk::Context& ctx, VkExtent2D extent, VkFormat format, std::string_view name);

  VkImage handle() const { return image_.get(); }
  VkExtent2D extent() const { return extent_; }
  VkFormat format() const { return format_; }
  explicit operator bool() const { return static_cast<bool>(image_); }

 private:
  VkExtent2D extent_{};
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  // The image goes before its memory is freed.
  vk::UniqueHandle<VkDeviceMemory> memory_;
  vk::UniqueHandle<VkImage> image_;
};

}  // namespace amrstream::app
