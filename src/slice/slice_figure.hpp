#pragma once
// A slice as a figure: the background channel in colours (or the LIC texture in grey, or the
// colours shaded by it), the field lines with arrows, a frame with axes in the data's units, and
// a colour bar below.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "even_lines.hpp"
#include "render/image/colour_bar.hpp"
#include "render/image/image.hpp"
#include "slice_plane.hpp"

namespace amrstream::slice {

struct SliceLayers {
  // The background's value at every pixel (x fastest, row 0 at the window's lower edge); empty:
  // no background. NaN where there is no data.
  std::vector<float> background;
  render::ColourBar colours;     // its map, scale, label and unit
  std::vector<float> lic;        // LIC intensities, as the background; empty: none
  std::vector<PlaneLine> lines;  // in plane coordinates
  float lineWidthPixels = 1.5f;
  render::Rgba8 lineColour{0, 0, 0, 235};
  // Per line, per point: the values the lines are coloured by, in lineColours (whose bar stacks
  // above the background's); empty: lineColour throughout. NaN: lineColour there.
  std::vector<std::vector<float>> lineColourValues;
  render::ColourBar lineColours;
  // Per line, per point: the values the lines' width follows, from a fifth of lineWidthPixels at
  // lineWidthRange[0] to lineWidthPixels at lineWidthRange[1]; empty: lineWidthPixels
  // throughout.
  std::vector<std::vector<float>> lineWidthValues;
  std::array<float, 2> lineWidthRange{0.0f, 1.0f};
  std::string lengthUnit;  // the coordinates', for the axes' names; may be empty
};

// The window's pixels (plane.width x plane.height) framed by axes, with the colour bars under
// them: the background's and the lines' colours'.
render::Image drawSliceFigure(const SlicePlane& plane, const SliceLayers& layers);

// Where the window's pixel (i, j) lands in drawSliceFigure's image: (left + i, top + height - 1 -
// j). Tests find the data's pixels through it.
struct FigureFrame {
  int left = 0, top = 0;
};
FigureFrame sliceFigureFrame(const SlicePlane& plane, const SliceLayers& layers);

// The LIC intensities spread to [0, 1]: the mean at 0.5, two standard deviations to either end
// (NaN stays NaN).
std::vector<float> stretchedLic(const std::vector<float>& lic);

}  // namespace amrstream::slice
