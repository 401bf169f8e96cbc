#include "render/image/colour_bar.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <glm/common.hpp>

#include "render/image/colour_bar_layout.hpp"
#include "render/image/font.hpp"

namespace amrstream::render {
namespace {

struct Palette {
  Rgba8 panel, frame, text;  // text: also the tick marks
};
constexpr Palette kDark{{0, 0, 0, 160}, {170, 170, 170, 255}, {240, 240, 240, 255}};
constexpr Palette kLight{{255, 255, 255, 200}, {90, 90, 90, 255}, {25, 25, 25, 255}};

void blendRect(Image& image, const PixelRect& rect, Rgba8 colour) {
  for (int y = rect.y; y < rect.y + rect.height; ++y) {
    for (int x = rect.x; x < rect.x + rect.width; ++x) {
      image.blend(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), colour);
    }
  }
}

// The 1-pixel outline just outside `rect`.
void drawFrameAround(Image& image, const PixelRect& rect, Rgba8 colour) {
  const int left = rect.x - 1, right = rect.x + rect.width;
  const int top = rect.y - 1, bottom = rect.y + rect.height;
  blendRect(image, {left, top, rect.width + 2, 1}, colour);
  blendRect(image, {left, bottom, rect.width + 2, 1}, colour);
  blendRect(image, {left, rect.y, 1, rect.height}, colour);
  blendRect(image, {right, rect.y, 1, rect.height}, colour);
}

// Column i at t = i / (width - 1), as colourMapTable samples a map.
std::vector<glm::vec3> gradientColours(const ColourBar& bar, int width) {
  const auto columns = static_cast<std::size_t>(width);
  if (bar.colours.empty()) return colourMapTable(bar.map, columns);
  std::vector<glm::vec3> table(columns);
  const std::size_t last = bar.colours.size() - 1;
  for (std::size_t i = 0; i < columns; ++i) {
    const double x = columns > 1 ? double(i) / double(columns - 1) * double(last) : 0.0;
    const std::size_t k = std::min(static_cast<std::size_t>(x), last > 0 ? last - 1 : 0);
    const float f = last > 0 ? static_cast<float>(x - double(k)) : 0.0f;
    table[i] = glm::mix(bar.colours[k], bar.colours[std::min(k + 1, last)], f);
  }
  return table;
}

void drawGradient(Image& image, const PixelRect& rect, const ColourBar& bar) {
  const std::vector<glm::vec3> table = gradientColours(bar, rect.width);
  for (int i = 0; i < rect.width; ++i) {
    const Rgba8 colour = toRgba8(table[static_cast<std::size_t>(i)]);
    for (int y = rect.y; y < rect.y + rect.height; ++y) {
      image.set(static_cast<std::uint32_t>(rect.x + i), static_cast<std::uint32_t>(y), colour);
    }
  }
}

}  // namespace

std::string colourBarTitle(const ColourBar& bar) {
  if (bar.unit.empty()) return bar.label;
  if (bar.label.empty()) return "[" + bar.unit + "]";
  return bar.label + " [" + bar.unit + "]";
}

std::string formatBarValue(double v) {
  if (v == 0.0) return "0";  // also -0
  return fmt::format("{:.3g}", v);
}

void drawColourBar(Image& image, const ColourBar& bar) {
  const std::optional<ColourBarLayout> layout = layoutColourBar(image.width, image.height, bar);
  if (!layout) return;
  const Palette& palette = bar.light ? kLight : kDark;
  blendRect(image, layout->panel, palette.panel);
  drawFrameAround(image, layout->gradient, palette.frame);
  drawGradient(image, layout->gradient, bar);
  drawPlacedText(image, layout->title, palette.text, layout->titlePixelSize);
  for (const PlacedTick& tick : layout->ticks) {
    blendRect(image, tick.mark, palette.text);
    drawPlacedText(image, tick.label, palette.text, layout->labelPixelSize);
  }
}

}  // namespace amrstream::render
