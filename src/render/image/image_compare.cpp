#include "render/image/image_compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace amrstream::render {
namespace {

std::uint32_t packedPixel(const Image& image, std::size_t pixel) {
  const std::uint8_t* p = image.rgba.data() + pixel * 4;
  return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3];
}

std::size_t pixelCount(const Image& image) { return std::size_t{image.width} * image.height; }

}  // namespace

ImageDifference compareImages(const Image& a, const Image& b, int threshold) {
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument(fmt::format("cannot compare a {}x{} image with a {}x{} image",
                                            a.width, a.height, b.width, b.height));
  }
  const std::size_t pixels = pixelCount(a);
  ImageDifference difference;
  if (pixels == 0) return difference;
  std::uint64_t sum = 0;
  std::size_t pixelsAbove = 0;
  for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
    int largest = 0;
    for (std::size_t channel = 0; channel < 3; ++channel) {
      const std::size_t i = pixel * 4 + channel;
      const int d = std::abs(int{a.rgba[i]} - int{b.rgba[i]});
      sum += static_cast<std::uint64_t>(d);
      largest = std::max(largest, d);
    }
    difference.maxAbsolute = std::max(difference.maxAbsolute, static_cast<std::uint8_t>(largest));
    if (largest > threshold) ++pixelsAbove;
  }
  difference.meanAbsolute = static_cast<double>(sum) / (3.0 * static_cast<double>(pixels));
  difference.fractionAbove = static_cast<double>(pixelsAbove) / static_cast<double>(pixels);
  return difference;
}

ImageContent describeContent(const Image& image) {
  const std::size_t pixels = pixelCount(image);
  ImageContent content;
  if (pixels == 0) return content;
  std::vector<std::uint32_t> colours(pixels);
  for (std::size_t pixel = 0; pixel < pixels; ++pixel) colours[pixel] = packedPixel(image, pixel);
  const std::uint32_t background = colours[0];
  const auto notBackground =
      std::ranges::count_if(colours, [&](auto c) { return c != background; });
  content.fractionNotBackground = static_cast<double>(notBackground) / static_cast<double>(pixels);
  std::ranges::sort(colours);
  content.distinctColours =
      static_cast<std::size_t>(std::unique(colours.begin(), colours.end()) - colours.begin());
  return content;
}

}  // namespace amrstream::render
