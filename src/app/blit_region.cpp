#include "app/blit_region.hpp"

#include <algorithm>
#include <cstdint>

namespace amrstream::app {

bool BlitRegion::covers(VkExtent2D target) const {
  return min.x == 0 && min.y == 0 && width() == target.width && height() == target.height;
}

BlitRegion fitCentred(VkExtent2D source, VkExtent2D target) {
  const uint64_t sw = source.width;
  const uint64_t sh = source.height;
  uint64_t width = target.width;
  uint64_t height = target.height;
  // Compare aspect ratios by cross-multiplying; the scaled side is rounded to the nearest pixel.
  if (sw * target.height >= sh * target.width) {
    height = std::max<uint64_t>(1, (target.width * sh + sw / 2) / sw);
  } else {
    width = std::max<uint64_t>(1, (target.height * sw + sh / 2) / sh);
  }
  const auto x = static_cast<int32_t>((target.width - width) / 2);
  const auto y = static_cast<int32_t>((target.height - height) / 2);
  return {{x, y}, {x + static_cast<int32_t>(width), y + static_cast<int32_t>(height)}};
}

}  // namespace amrstream::app
