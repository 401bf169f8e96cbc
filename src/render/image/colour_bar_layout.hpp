#pragma once
// Where drawColourBar puts each part of a colour bar, in pixels; exposed so that tests (and a
// viewer drawing the same legend another way) can find them. Everything lies inside the image.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/image/colour_bar.hpp"
#include "render/image/placed_text.hpp"

namespace amrstream::render {

constexpr std::uint32_t kMinColourBarImageSide = 128;

struct PlacedTick {
  double value = 0;
  // The gradient's column of the value: gradient.x + round(position * (gradient.width - 1)).
  int x = 0;
  // The mark: from the gradient's bottom edge (over its frame) down, covering column x, one
  // pixel wide or two at large sizes.
  PixelRect mark;
  // Centred under the mark (moved inwards near the panel's sides). Its text is empty when it
  // was left out: for crowding its neighbour (the first and last ticks keep theirs, unless those
  // two would touch: then only the first), or for being wider than the panel.
  PlacedText label;
};

struct ColourBarLayout {
  // The tick labels' and the title's font sizes: about 1.6 % and 2 % of the image's shorter
  // side, the labels' within [11, 48] px; smaller where the image is too short for the panel.
  int labelPixelSize = 11;
  int titlePixelSize = 13;
  // The translucent backdrop; every part below lies inside it.
  PixelRect panel;
  // At least max(64, width / 3) wide unless the image is too narrow, framed by a 1-pixel border
  // just outside.
  PixelRect gradient;
  // Centred above the gradient; empty text when the bar has neither label nor unit.
  PlacedText title;
  // scaleTicks(scale, ...) from left to right; for a scale checkScale refuses, the two ends
  // labelled with formatBarValue (one tick in the middle when min == max).
  std::vector<PlacedTick> ticks;
};

// nullopt when either side of the image is below kMinColourBarImageSide.
std::optional<ColourBarLayout> layoutColourBar(std::uint32_t width, std::uint32_t height,
                                               const ColourBar& bar);

}  // namespace amrstream::render
