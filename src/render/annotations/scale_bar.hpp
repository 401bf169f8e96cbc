#pragma once
// The scale bar for figures: above the triad on the left, a horizontal bar as long as a round
// physical length looks, labelled with that length and the unit.

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>

#include "bricks/amr_field.hpp"
#include "render/camera.hpp"
#include "render/image/image.hpp"
#include "render/image/placed_text.hpp"

namespace amrstream::render {

struct ScaleBarLayout {
  int labelPixelSize = 11;
  float thickness = 2.0f;
  float endHeight = 6.0f;  // of the upright strokes at the bar's ends, centred on it
  // Pixels per physical unit in the plane through the camera's target across the view; 0 when
  // the view has no scale (a distance or field of view of 0, an empty image).
  double pixelsPerUnit = 0;
  // Physical, in the input's units: the largest 1, 2 or 5 x 10^k whose bar spans at most a
  // quarter of the image's width (and so at least a tenth); 0 when pixelsPerUnit is.
  double length = 0;
  // The bar's centre line, left to right: end.x - start.x = length * pixelsPerUnit.
  glm::vec2 start{0.0f}, end{0.0f};
  PlacedText label;  // "0.2 kpc", or "0.2" without a unit, centred above the bar
};

// `unitLength`: the physical length of one unit of the camera's space (the scene's, see
// scene_space.hpp, which is the same along every axis). In perspective, things nearer or further
// than the target look larger or smaller than the bar says; in orthographic projection it holds
// everywhere. labelPixelSize: overlayLabelPixelSize suits; the bar sits above the triad laid out
// with the same size.
ScaleBarLayout layoutScaleBar(const OrbitCamera& camera, std::uint32_t width, std::uint32_t height,
                              double unitLength, std::string unit, int labelPixelSize);

// The bar and its label in `colour`; nothing when the layout's length is 0.
void drawScaleBar(Image& image, const ScaleBarLayout& layout, Rgba8 colour);

}  // namespace amrstream::render
