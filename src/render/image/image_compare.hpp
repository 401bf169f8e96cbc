#pragma once
// Measures for checking rendered images: how far two images are apart, and whether an image
// shows anything at all.

#include <cstddef>
#include <cstdint>

#include "render/image/image.hpp"

namespace amrstream::render {

// Over the R, G and B channels (alpha is ignored).
struct ImageDifference {
  double meanAbsolute = 0;       // mean |a - b| over every channel of every pixel
  std::uint8_t maxAbsolute = 0;  // the largest |a - b| of any channel
  double fractionAbove = 0;      // fraction of pixels with some channel differing by > threshold
};

// Images of different sizes throw std::invalid_argument naming both sizes; two empty images
// differ by nothing.
ImageDifference compareImages(const Image& a, const Image& b, int threshold);

// Counts whole RGBA values; the background is the colour of pixel (0, 0).
struct ImageContent {
  std::size_t distinctColours = 0;
  double fractionNotBackground = 0;
};

ImageContent describeContent(const Image& image);

}  // namespace amrstream::render
