#include "render/annotations/scale_bar.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "render/annotations/line_drawing.hpp"
#include "render/annotations/overlay_text.hpp"
#include "render/annotations/triad.hpp"

namespace amrstream::render {
namespace {

constexpr double kLongestFraction = 0.25;  // of the image's width

// The largest 1, 2 or 5 x 10^k at most `most` (> 0).
double roundLengthAtMost(double most) {
  const double decade = std::pow(10.0, std::floor(std::log10(most)));
  for (const double factor : {5.0, 2.0, 1.0})
    if (factor * decade <= most * (1.0 + 1e-9)) return factor * decade;
  return decade;
}

// The view's height in the camera's units is 2 distance tan(fovY / 2) at the target, in either
// projection (camera.hpp).
double pixelsPerPhysicalUnit(const OrbitCamera& camera, std::uint32_t height, double unitLength) {
  const double viewHeight = 2.0 * camera.distance * halfHeightAtUnitDistance(camera);
  const double pixels = height / (viewHeight * std::abs(unitLength));
  return std::isfinite(pixels) && pixels > 0.0 ? pixels : 0.0;
}

}  // namespace

ScaleBarLayout layoutScaleBar(const OrbitCamera& camera, std::uint32_t width, std::uint32_t height,
                              double unitLength, std::string unit, int labelPixelSize) {
  ScaleBarLayout layout;
  layout.labelPixelSize = labelPixelSize;
  layout.thickness = std::max(2.0f, labelPixelSize / 6.0f);
  layout.endHeight = std::max(6.0f, 0.6f * labelPixelSize);
  layout.pixelsPerUnit = pixelsPerPhysicalUnit(camera, height, unitLength);
  if (layout.pixelsPerUnit == 0.0 || width == 0) return layout;
  layout.length = roundLengthAtMost(kLongestFraction * width / layout.pixelsPerUnit);

  const PixelRect triad = triadArea(height, labelPixelSize);
  const float gap = std::max(2.0f, 0.25f * labelPixelSize);
  const float barY = triad.y - gap - 0.5f * layout.endHeight;
  layout.start = {static_cast<float>(triad.x), barY};
  layout.end = layout.start + glm::vec2(layout.length * layout.pixelsPerUnit, 0.0f);

  std::string text = fmt::format("{:g}", layout.length);
  if (!unit.empty()) text += " " + unit;
  const glm::vec2 aboveMiddle(0.5f * (layout.start.x + layout.end.x),
                              barY - 0.5f * layout.endHeight - gap);
  layout.label = placeTextBeyond(std::move(text), aboveMiddle, {0.0f, -1.0f}, labelPixelSize);
  // A label wider than the bar starts where the bar does.
  const int shift = std::max(0, triad.x - layout.label.box.x);
  layout.label.x += shift, layout.label.box.x += shift;
  return layout;
}

void drawScaleBar(Image& image, const ScaleBarLayout& layout, Rgba8 colour) {
  if (layout.length == 0.0) return;
  drawLine(image, layout.start, layout.end, layout.thickness, colour);
  // The ends' strokes lie inside the bar's length.
  const glm::vec2 inset(0.5f * layout.thickness, 0.0f), halfUp(0.0f, 0.5f * layout.endHeight);
  for (const glm::vec2 end : {layout.start + inset, layout.end - inset})
    drawLine(image, end - halfUp, end + halfUp, layout.thickness, colour);
  drawPlacedText(image, layout.label, colour, layout.labelPixelSize);
}

}  // namespace amrstream::render
