#pragma once
// Axes around a box for figures: for each of x, y and z, one of the box's four edges along it,
// the one outermost on screen, with tick marks at round physical values pointing away from the
// box, their values beyond the marks and the axis's name beyond those. Drawn over the rendered
// image like the colour bar; layoutAxes says where every part goes, so that tests and callers
// can find them.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "bricks/amr_field.hpp"
#include "render/camera.hpp"
#include "render/image/image.hpp"
#include "render/image/placed_text.hpp"

namespace amrstream::render {

// An axis whose outermost edge projects shorter than this is seen (nearly) end-on: it gets none.
constexpr float kMinAxisEdgePixels = 4.0f;

struct AxisTick {
  double value = 0;         // physical, along the axis: a round value inside the box's range
  glm::vec3 point{0.0f};    // where the value lies on the edge, in cell units
  glm::vec2 pixel{0.0f};    // projectToImage(camera, width, height, point)
  glm::vec2 markEnd{0.0f};  // the mark runs from pixel to here, `outward`
  // Beyond the mark; empty text (and zero width) when it was left out for overlapping another
  // label.
  PlacedText label;
};

struct AxisLayout {
  int axis = 0;  // 0, 1, 2: x, y, z
  // False when every edge along the axis projects shorter than kMinAxisEdgePixels or reaches
  // behind a perspective eye; the fields below are then left as they are.
  bool shown = false;
  // The chosen edge in cell units, at the box's lower and upper physical bound of the axis, and
  // their projections.
  glm::vec3 edgeStart{0.0f}, edgeEnd{0.0f};
  glm::vec2 pixelStart{0.0f}, pixelEnd{0.0f};
  glm::vec2 outward{0.0f};      // unit, across the edge on screen, away from the box's centre
  std::vector<AxisTick> ticks;  // increasing values
  // "x", "y" or "z" with the unit ("x [cm]") beyond the middle of the edge, past the tick labels.
  PlacedText name;
};

struct AxesLayout {
  int labelPixelSize = 11;
  float lineWidth = 1.0f;  // of the edges and the marks
  std::array<AxisLayout, 3> axes;
};

// The axes of the box [lowerPhysical, upperPhysical] (physical coordinates, lower <= upper on
// each axis; `transform` maps them to the camera's cell units) seen by `camera` in a width x
// height image, with labels of labelPixelSize px (overlayLabelPixelSize suits); `unit` (the
// coordinates', may be empty) follows the axes' names.
//
// Each axis takes the edge along it on the box's projected outline whose midpoint lies furthest
// from the box's projected centre, measured across the edge on screen; none when that edge is
// shorter than kMinAxisEdgePixels. In perspective, looking into a face, the edges along the view
// all lie inside the outline: then the furthest of those. Up to five ticks (fewer on short
// edges) at the values scaleTicks gives for the box's range. A label that would overlap one
// placed before it is left out: the axes' names come first, then the ticks' labels axis by axis.
// Nothing is shown when the box's centre lies behind a perspective eye.
AxesLayout layoutAxes(const OrbitCamera& camera, std::uint32_t width, std::uint32_t height,
                      glm::dvec3 lowerPhysical, glm::dvec3 upperPhysical,
                      const WorldTransform& transform, int labelPixelSize,
                      const std::string& unit = {});

// The edges, marks and labels of every shown axis in `colour`, clipped to the image.
void drawAxes(Image& image, const AxesLayout& layout, Rgba8 colour);

}  // namespace amrstream::render
