#pragma once
// The colour legend burnt into rendered images: a horizontal gradient of the colour map on a
// translucent dark panel near the bottom-right corner, the title above it, and tick marks with
// their values below.

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "render/image/colour_map.hpp"
#include "render/image/colour_scale.hpp"
#include "render/image/image.hpp"

namespace amrstream::render {

struct ColourBar {
  ColourMap map = ColourMap::Viridis;
  ColourScale scale;  // the values along the gradient, which its ticks show
  std::string label;  // the field's name; may be empty
  std::string unit;   // may be empty
  // The gradient's colours from its low end to its high end, evenly spaced and interpolated
  // linearly (a transfer function's, say); empty: the map's.
  std::vector<glm::vec3> colours;
  // Bars stack up from the bottom-right corner: 0 is the lowest, 1 the one above it, ...
  int stack = 0;
  // A light translucent panel with dark text, for light backgrounds; else dark with light text.
  bool light = false;
};

// "label [unit]", or whichever of the two is not empty; shortened with an ellipsis when it does
// not fit above the gradient.
std::string colourBarTitle(const ColourBar& bar);

// Three significant digits, as short as possible: "0", "0.25", "1.5e+03", "-3.2e-05". Labels the
// ends of a scale that has no ticks (see colour_bar_layout.hpp).
std::string formatBarValue(double v);

// Draws nothing on images smaller than 128x128 (kMinColourBarImageSide); see colour_bar_layout.hpp
// for where each part goes. Column i of the gradient is colourMapTable(map, gradient width)[i]:
// the map at t = i / (width - 1), so that a tick at t sits on the column of its colour.
void drawColourBar(Image& image, const ColourBar& bar);

}  // namespace amrstream::render
