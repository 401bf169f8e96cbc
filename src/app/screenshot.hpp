#pragma once
// Screenshot: what the window showed in one frame (the renderer's image with the overlay), as
// 8-bit RGBA, row-major, top row first, alpha 255 (the window is opaque whatever the alpha the
// swapchain image holds). Ready for a PNG writer.

#include <vulkan/vulkan.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace amrstream::app {

struct Screenshot {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba;  // width * height * 4 bytes

  std::array<uint8_t, 4> pixel(uint32_t x, uint32_t y) const {
    const size_t i = (size_t(y) * width + x) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
  }
};

using ScreenshotCallback = std::function<void(Screenshot)>;

// Tightly packed texels of a swapchain image in `format` (B8G8R8A8 or R8G8B8A8, UNORM or SRGB:
// those Swapchain chooses) as a Screenshot. Throws std::invalid_argument for other formats or a
// size that does not match `extent`.
Screenshot toScreenshot(std::span<const std::byte> texels, VkExtent2D extent, VkFormat format);

}  // namespace amrstream::app
