#pragma once
// The labels of overlays (axes, triad, scale bar): where they go and how they are drawn (their
// size: overlayLabelPixelSize in font.hpp). Placed text is the colour bar's PlacedText.

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>

#include "render/image/colour_bar_layout.hpp"
#include "render/image/font.hpp"
#include "render/image/image.hpp"

namespace amrstream::render {

// Text whose box (Font::textWidth by the line's height) is centred on `centre`.
PlacedText placeTextCentredOn(std::string text, glm::vec2 centre, int pixelSize);

// Text just beyond `anchor` in the unit `direction`: its box lies past the line through `anchor`
// across `direction` and touches it, centred on the ray from `anchor` along `direction`.
PlacedText placeTextBeyond(std::string text, glm::vec2 anchor, glm::vec2 direction, int pixelSize);

// Whether the boxes come within `spacing` pixels of each other.
bool boxesOverlap(const PixelRect& a, const PixelRect& b, int spacing);

// Nothing for empty text.
void drawPlacedText(Image& image, const PlacedText& text, Rgba8 colour, int pixelSize);

}  // namespace amrstream::render
