#include "render/image/image.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace amrstream::render {
namespace {

std::uint8_t unitToByte(float v) {
  if (!(v > 0.0f)) return 0;  // also NaN
  if (v >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::lround(v * 255.0f));
}

// (s * a + d * (255 - a)) / 255, rounded to nearest: exact for a = 0 and a = 255.
std::uint8_t mix(std::uint8_t source, std::uint8_t destination, std::uint8_t alpha) {
  const unsigned sum = unsigned{source} * alpha + unsigned{destination} * (255u - alpha);
  return static_cast<std::uint8_t>((sum + 127u) / 255u);
}

}  // namespace

Rgba8 toRgba8(glm::vec3 srgb, std::uint8_t alpha) {
  return {unitToByte(srgb.r), unitToByte(srgb.g), unitToByte(srgb.b), alpha};
}

Image::Image(std::uint32_t w, std::uint32_t h, Rgba8 fill) : width(w), height(h) {
  const std::size_t pixels = std::size_t{w} * h;
  if (pixels > std::numeric_limits<std::size_t>::max() / 4) {
    throw std::length_error(fmt::format("image of {}x{} pixels is too large", w, h));
  }
  rgba.resize(pixels * 4);
  for (std::size_t i = 0; i < rgba.size(); i += 4) {
    rgba[i] = fill.r;
    rgba[i + 1] = fill.g;
    rgba[i + 2] = fill.b;
    rgba[i + 3] = fill.a;
  }
}

std::size_t Image::offsetOf(std::uint32_t x, std::uint32_t y) const {
  if (x >= width || y >= height) {
    throw std::out_of_range(
        fmt::format("pixel ({}, {}) is outside the {}x{} image", x, y, width, height));
  }
  return (std::size_t{y} * width + x) * 4;
}

Rgba8 Image::at(std::uint32_t x, std::uint32_t y) const {
  const std::size_t i = offsetOf(x, y);
  return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
}

void Image::set(std::uint32_t x, std::uint32_t y, Rgba8 c) {
  const std::size_t i = offsetOf(x, y);
  rgba[i] = c.r;
  rgba[i + 1] = c.g;
  rgba[i + 2] = c.b;
  rgba[i + 3] = c.a;
}

void Image::blend(std::uint32_t x, std::uint32_t y, Rgba8 c) {
  const Rgba8 d = at(x, y);
  if (d.a == 255) {
    set(x, y, {mix(c.r, d.r, c.a), mix(c.g, d.g, c.a), mix(c.b, d.b, c.a), 255});
    return;
  }
  // Over a translucent pixel: Porter-Duff "over" in straight (not premultiplied) alpha.
  const double a = c.a / 255.0, b = d.a / 255.0 * (1.0 - a), out = a + b;
  if (out <= 0.0) return;
  const auto channel = [&](std::uint8_t source, std::uint8_t destination) {
    return static_cast<std::uint8_t>(std::lround((source * a + destination * b) / out));
  };
  set(x, y,
      {channel(c.r, d.r), channel(c.g, d.g), channel(c.b, d.b),
       static_cast<std::uint8_t>(std::lround(out * 255.0))});
}

}  // namespace amrstream::render
