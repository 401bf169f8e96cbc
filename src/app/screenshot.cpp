#include "app/screenshot.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace amrstream::app {

Screenshot toScreenshot(std::span<const std::byte> texels, VkExtent2D extent, VkFormat format) {
  bool bgra = false;
  switch (format) {
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
      bgra = true;
      break;
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
      break;
    default:
      throw std::invalid_argument(
          fmt::format("toScreenshot: VkFormat {} is not 8-bit RGBA or BGRA", int(format)));
  }
  const size_t size = size_t(extent.width) * extent.height * 4;
  if (texels.size() != size) {
    throw std::invalid_argument(fmt::format("toScreenshot: {} bytes for a {}x{} image",
                                            texels.size(), extent.width, extent.height));
  }
  Screenshot shot{extent.width, extent.height, std::vector<uint8_t>(size)};
  for (size_t i = 0; i < size; i += 4) {
    const auto b0 = static_cast<uint8_t>(texels[i]);
    const auto b2 = static_cast<uint8_t>(texels[i + 2]);
    shot.rgba[i] = bgra ? b2 : b0;
    shot.rgba[i + 1] = static_cast<uint8_t>(texels[i + 1]);
    shot.rgba[i + 2] = bgra ? b0 : b2;
    shot.rgba[i + 3] = 255;
  }
  return shot;
}

}  // namespace amrstream::app
