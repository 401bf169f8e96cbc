#pragma once
// Where drawColourBar puts each part of a colour bar, in pixels; exposed so that tests (and a
// viewer drawing the same legend another way) can find them. Everything lies inside the image.

#include <cstdint>
#include <optional>
#include <string>

#include "render/image/colour_bar.hpp"

namespace amrstream::render {

constexpr std::uint32_t kMinColourBarImageSide = 128;

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

struct PlacedText {
  int x = 0, y = 0;  // top-left corner
  std::string text;
};

struct ColourBarLayout {
  // Text scale: 1 below 512 px of image width, 2 from 512, 3 from 1536; less when too short.
  int scale = 1;
  // The translucent backdrop; every part below lies inside it.
  PixelRect panel;
  // At least max(64, width / 3) wide, framed by a 1-pixel border just outside.
  PixelRect gradient;
  // Centred above the gradient; empty text when the bar has no label.
  PlacedText label;
  // Under the gradient's left and right ends, normally two characters apart or more. In narrow
  // images they come closer, and two values as long as -1.23e+100 overlap at 128 px.
  PlacedText minValue;
  PlacedText maxValue;
};

// nullopt when either side of the image is below kMinColourBarImageSide.
std::optional<ColourBarLayout> layoutColourBar(std::uint32_t width, std::uint32_t height,
                                               const ColourBar& bar);

}  // namespace amrstream::render
