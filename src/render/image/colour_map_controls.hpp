#pragma once
// The published control points the colour maps interpolate. Internal to colour_map.cpp.

#include <span>

#include "render/image/colour_map.hpp"

namespace amrstream::render::detail {

struct ColourControl {
  float t;        // increasing, first 0, last 1
  float r, g, b;  // sRGB in [0,1]
};

std::span<const ColourControl> colourControls(ColourMap map);

}  // namespace amrstream::render::detail
