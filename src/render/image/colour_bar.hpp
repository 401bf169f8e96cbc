#pragma once
// The colour legend burnt into rendered images: a horizontal gradient of the colour map on a
// translucent dark panel near the bottom-right corner, the label above it, the range ends below.

#include <string>

#include "render/image/colour_map.hpp"
#include "render/image/image.hpp"

namespace amrstream::render {

struct ColourBar {
  ColourMap map = ColourMap::Viridis;
  double min = 0, max = 1;  // the values at the gradient's left and right ends
  std::string label;        // may be empty; shortened with ".." when it does not fit
};

// Three significant digits, as short as possible: "0", "0.25", "1.5e+03", "-3.2e-05".
std::string formatBarValue(double v);

// Draws nothing on images smaller than 128x128 (kMinColourBarImageSide); see colour_bar_layout.hpp
// for where each part goes. Column i of the gradient is colourMapTable(map, gradient width)[i].
void drawColourBar(Image& image, const ColourBar& bar);

}  // namespace amrstream::render
