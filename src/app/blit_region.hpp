#pragma once
// Where the renderer's frame lands on a swapchain image of another size: scaled to fit with its
// aspect ratio kept and centred, so that a window of another shape shows bars (the clear colour)
// rather than a stretched frame.

#include <vulkan/vulkan.h>

namespace amrstream::app {

struct BlitRegion {
  VkOffset2D min{};  // inclusive
  VkOffset2D max{};  // exclusive, as vkCmdBlitImage's second offset

  uint32_t width() const { return static_cast<uint32_t>(max.x - min.x); }
  uint32_t height() const { return static_cast<uint32_t>(max.y - min.y); }
  // True when no bar is left to clear.
  bool covers(VkExtent2D target) const;
};

// `source` and `target` must not be empty.
BlitRegion fitCentred(VkExtent2D source, VkExtent2D target);

}  // namespace amrstream::app
