#pragma once
// Text burnt into an image at a known place, with the box it takes: what the colour bar and the
// overlays (axes, triad, scale bar) lay out, and tests look for.

#include <string>

#include "render/image/image.hpp"

namespace amrstream::render {

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
};

struct PlacedText {
  std::string text;
  int x = 0;         // where the pen starts
  int baseline = 0;  // the row below the ink of letters without descenders (Font::drawText)
  // From x over Font::textWidth, and from baseline - ascent to baseline + descent.
  PixelRect box;
};

// `text` in defaultFont() at pixelSize with its box's top-left corner at (x, top).
PlacedText placeText(std::string text, int x, int top, int pixelSize);

// Draws placed text in `colour` (nothing for empty text).
void drawPlacedText(Image& image, const PlacedText& text, Rgba8 colour, int pixelSize);

// Whether the boxes come within `spacing` pixels of each other.
bool boxesOverlap(const PixelRect& a, const PixelRect& b, int spacing);

}  // namespace amrstream::render
