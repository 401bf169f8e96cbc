#pragma once
// An 8-bit RGBA raster held on the CPU: what the renderer reads back, annotates and writes as PNG.
// Invariant kept by the constructor: rgba.size() == width * height * 4 (the members are public
// for the renderer's bulk copies; code that resizes them must keep it). Colours are sRGB-encoded
// and not premultiplied.

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace amrstream::render {

struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Rgba8&) const = default;
};

// Rounds each channel of an sRGB colour in [0,1] to 8 bits; values outside are clamped, NaN -> 0.
Rgba8 toRgba8(glm::vec3 srgb, std::uint8_t alpha = 255);

struct Image {  // row-major, top row first
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes

  Image() = default;
  Image(std::uint32_t w, std::uint32_t h, Rgba8 fill = {});

  bool empty() const { return width == 0 || height == 0; }

  // Pixel access; coordinates outside the image throw std::out_of_range.
  Rgba8 at(std::uint32_t x, std::uint32_t y) const;
  void set(std::uint32_t x, std::uint32_t y, Rgba8 c);
  // Source-over with c.a as coverage: the colour channels move towards c; an opaque pixel stays
  // opaque, a translucent one gets the "over" operator's alpha.
  void blend(std::uint32_t x, std::uint32_t y, Rgba8 c);

 private:
  std::size_t offsetOf(std::uint32_t x, std::uint32_t y) const;
};

}  // namespace amrstream::render
