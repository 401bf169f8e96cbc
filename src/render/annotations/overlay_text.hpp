#pragma once
// Where the labels of overlays (axes, triad, scale bar) go: centred on a point or just beyond it
// (their size: overlayLabelPixelSize in font.hpp; drawing and overlap: placed_text.hpp).

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>

#include "render/image/font.hpp"
#include "render/image/placed_text.hpp"

namespace amrstream::render {

// Text whose box (Font::textWidth by the line's height) is centred on `centre`.
PlacedText placeTextCentredOn(std::string text, glm::vec2 centre, int pixelSize);

// Text just beyond `anchor` in the unit `direction`: its box lies past the line through `anchor`
// across `direction` and touches it, centred on the ray from `anchor` along `direction`.
PlacedText placeTextBeyond(std::string text, glm::vec2 anchor, glm::vec2 direction, int pixelSize);

}  // namespace amrstream::render
