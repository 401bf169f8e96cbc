#include "slice_figure.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/annotations/line_drawing.hpp"
#include "render/image/colour_bar_layout.hpp"
#include "render/image/colour_map.hpp"
#include "render/image/colour_scale.hpp"
#include "render/image/font.hpp"
#include "render/image/placed_text.hpp"

namespace amrstream::slice {

namespace {

using render::Image;
using render::Rgba8;

constexpr Rgba8 kPaper{255, 255, 255, 255};
constexpr Rgba8 kNoData{217, 217, 217, 255};
constexpr Rgba8 kInk{25, 25, 25, 255};
constexpr Rgba8 kHalo{255, 255, 255, 90};
constexpr int kMostTicks = 6;

std::vector<render::ScaleTick> axisTicks(double lower, double upper) {
  render::ColourScale scale;
  scale.min = lower;
  scale.max = upper;
  return render::scaleTicks(scale, kMostTicks);
}

std::string axisName(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " [" + unit + "]";
}

struct Layout {
  int labelPixels = 11, mark = 4, lineHeight = 13;
  int left = 0, top = 0, right = 0, bottom = 0;
  std::uint32_t width = 0, height = 0;  // the whole image
};

// The colour bars under the axes, the lowest first.
std::vector<render::ColourBar> colourBars(const SliceLayers& layers) {
  std::vector<render::ColourBar> bars;
  if (!layers.background.empty()) bars.push_back(layers.colours);
  if (!layers.lineColourValues.empty()) bars.push_back(layers.lineColours);
  for (std::size_t i = 0; i < bars.size(); ++i) {
    bars[i].stack = int(i);
    bars[i].light = true;
  }
  return bars;
}

Layout layoutFigure(const SlicePlane& plane, const SliceLayers& layers) {
  const render::Font& font = render::defaultFont();
  Layout layout;
  layout.labelPixels = render::overlayLabelPixelSize(plane.width, plane.height);
  layout.mark = std::max(4, layout.labelPixels / 3);
  layout.lineHeight = font.lineMetrics(layout.labelPixels).height();
  int widestY = 0;
  for (const render::ScaleTick& tick : axisTicks(plane.lower.y, plane.upper.y))
    widestY = std::max(widestY, font.textWidth(tick.label, layout.labelPixels));
  int lastX = 0;
  for (const render::ScaleTick& tick : axisTicks(plane.lower.x, plane.upper.x))
    lastX = font.textWidth(tick.label, layout.labelPixels);
  layout.left = layout.mark + 6 + widestY + 10;
  layout.top = layout.lineHeight + 10;
  layout.right = std::max(12, lastX / 2 + 6);
  const int axesBelow = layout.mark + 6 + 2 * layout.lineHeight + 14;
  layout.bottom = axesBelow;
  layout.width = std::uint32_t(layout.left + int(plane.width) + layout.right);
  layout.height = std::uint32_t(layout.top + int(plane.height) + layout.bottom);
  const std::vector<render::ColourBar> bars = colourBars(layers);
  if (bars.empty()) return layout;
  // The colour bars sit at the image's bottom right, below the axes' labels.
  for (int attempt = 0; attempt < 4; ++attempt) {
    const auto bar = render::layoutColourBar(layout.width, layout.height, bars.back());
    if (!bar) break;
    const int wanted = layout.top + int(plane.height) + axesBelow;
    if (bar->panel.y >= wanted) break;
    layout.bottom += wanted - bar->panel.y;
    layout.height = std::uint32_t(layout.top + int(plane.height) + layout.bottom);
  }
  return layout;
}

// The colour lightened or darkened by the LIC texture (0.5 leaves it): scaled, and moved by a
// share of the range too, so that the texture shows on dark colours as well as light ones.
Rgba8 shade(Rgba8 colour, float lic) {
  const float change = lic - 0.5f;
  const auto shaded = [change](std::uint8_t c) {
    return std::uint8_t(
        std::clamp(std::lround(float(c) * (1.0f + 0.7f * change) + 110.0f * change), 0L, 255L));
  };
  return {shaded(colour.r), shaded(colour.g), shaded(colour.b), colour.a};
}

void drawPixels(Image& image, const Layout& layout, const SlicePlane& plane,
                const SliceLayers& layers) {
  const std::vector<float> lic = stretchedLic(layers.lic);
  const render::ColourBar& bar = layers.colours;
  for (std::uint32_t j = 0; j < plane.height; ++j) {
    for (std::uint32_t i = 0; i < plane.width; ++i) {
      const std::size_t n = i + std::size_t(plane.width) * j;
      Rgba8 colour = kNoData;
      const bool hasBackground = !layers.background.empty();
      if (hasBackground && std::isfinite(layers.background[n])) {
        const double t = bar.scale.position(layers.background[n]);
        colour = render::toRgba8(render::sampleColourMap(bar.map, float(t)));
      }
      if (!lic.empty() && std::isfinite(lic[n])) {
        if (hasBackground && std::isfinite(layers.background[n]))
          colour = shade(colour, lic[n]);
        else if (!hasBackground)
          colour = render::toRgba8(glm::vec3(lic[n]));
      }
      image.set(std::uint32_t(layout.left) + i, std::uint32_t(layout.top) + plane.height - 1 - j,
                colour);
    }
  }
}

glm::vec2 toPixel(const Layout& layout, const SlicePlane& plane, glm::dvec2 p) {
  const glm::dvec2 t = (p - plane.lower) / (plane.upper - plane.lower);
  return {float(layout.left + t.x * plane.width), float(layout.top + (1.0 - t.y) * plane.height)};
}

float arrowLength(float width) { return 3.0f * width + 4.0f; }

// Whether an arrow at `tip` stays inside the window's pixels.
bool insideByAnArrow(const Layout& layout, const SlicePlane& plane, glm::vec2 tip, float width) {
  const float margin = arrowLength(width) + width;
  return tip.x >= float(layout.left) + margin &&
         tip.x <= float(layout.left + int(plane.width)) - margin &&
         tip.y >= float(layout.top) + margin &&
         tip.y <= float(layout.top + int(plane.height)) - margin;
}

// A chevron pointing along `direction` with its tip at `tip`.
void drawArrow(Image& image, glm::vec2 tip, glm::vec2 direction, float width, Rgba8 colour) {
  const float length = arrowLength(width);
  const float c = std::cos(0.45f), s = std::sin(0.45f);
  const glm::vec2 back = -direction;
  const glm::vec2 left{back.x * c - back.y * s, back.x * s + back.y * c};
  const glm::vec2 right{back.x * c + back.y * s, -back.x * s + back.y * c};
  render::drawLine(image, tip, tip + length * left, width, colour, render::LineCap::Round);
  render::drawLine(image, tip, tip + length * right, width, colour, render::LineCap::Round);
}

// The width of the segment from point k - 1 to point k of line `index`.
float segmentWidth(const SliceLayers& layers, std::size_t index, std::size_t k) {
  if (layers.lineWidthValues.empty()) return layers.lineWidthPixels;
  const std::vector<float>& values = layers.lineWidthValues[index];
  const float value = 0.5f * (values[k - 1] + values[k]);
  const auto [low, high] = layers.lineWidthRange;
  const float t = high > low ? std::clamp((value - low) / (high - low), 0.0f, 1.0f) : 1.0f;
  return layers.lineWidthPixels * (0.2f + 0.8f * (std::isfinite(t) ? t : 0.0f));
}

Rgba8 segmentColour(const SliceLayers& layers, std::size_t index, std::size_t k) {
  if (layers.lineColourValues.empty()) return layers.lineColour;
  const std::vector<float>& values = layers.lineColourValues[index];
  const double value = 0.5 * (double(values[k - 1]) + double(values[k]));
  if (!std::isfinite(value)) return layers.lineColour;
  const render::ColourBar& bar = layers.lineColours;
  return render::toRgba8(render::sampleColourMap(bar.map, float(bar.scale.position(value))));
}

// The lines with their arrows; `halo` widens them and draws them all in its colour.
void drawLinePass(Image& image, const Layout& layout, const SlicePlane& plane,
                  const SliceLayers& layers, std::optional<Rgba8> halo) {
  const std::vector<PlaneLine>& lines = layers.lines;
  const double arrowEvery =
      0.3 * std::min(plane.upper.x - plane.lower.x, plane.upper.y - plane.lower.y);
  for (std::size_t index = 0; index < lines.size(); ++index) {
    const PlaneLine& line = lines[index];
    // Each line's arrows start at its own phase, so that lines entering side by side do not
    // align their arrows in rows.
    const double phase = std::fmod(0.25 + 0.618034 * double(index), 1.0);
    double arc = 0.0, nextArrow = phase * arrowEvery;
    for (std::size_t k = 1; k < line.points.size(); ++k) {
      const glm::vec2 from = toPixel(layout, plane, line.points[k - 1]);
      const glm::vec2 to = toPixel(layout, plane, line.points[k]);
      const float base = segmentWidth(layers, index, k), width = base + (halo ? 1.0f : 0.0f);
      const Rgba8 colour = halo ? *halo : segmentColour(layers, index, k);
      render::drawLine(image, from, to, width, colour, render::LineCap::Round);
      arc += glm::distance(line.points[k - 1], line.points[k]);
      const float pixels = glm::distance(from, to);
      if (arc >= nextArrow && pixels > 0.0f && insideByAnArrow(layout, plane, to, base)) {
        drawArrow(image, to, (to - from) / pixels, width, colour);
        nextArrow += arrowEvery;
      }
    }
  }
}

// The lines with arrows, twice: a light halo under the dark lines, so that they show on dark
// colours as on light ones.
void drawLines(Image& image, const Layout& layout, const SlicePlane& plane,
               const SliceLayers& layers) {
  drawLinePass(image, layout, plane, layers, kHalo);
  drawLinePass(image, layout, plane, layers, std::nullopt);
}

void drawAxes(Image& image, const Layout& layout, const SlicePlane& plane,
              const std::string& unit) {
  const render::Font& font = render::defaultFont();
  // The frame runs through the pixels just outside the data's; the ticks sit on the data's edges.
  const float x0 = float(layout.left) - 0.5f, x1 = float(layout.left + int(plane.width)) + 0.5f;
  const float y0 = float(layout.top) - 0.5f, y1 = float(layout.top + int(plane.height)) + 0.5f;
  const float dataLeft = float(layout.left), dataBottom = float(layout.top + int(plane.height));
  render::drawLine(image, {x0, y0}, {x1, y0}, 1.0f, kInk);
  render::drawLine(image, {x0, y1}, {x1, y1}, 1.0f, kInk);
  render::drawLine(image, {x0, y0}, {x0, y1}, 1.0f, kInk);
  render::drawLine(image, {x1, y0}, {x1, y1}, 1.0f, kInk);
  const int px = layout.labelPixels;
  const render::LineMetrics metrics = font.lineMetrics(px);
  for (const render::ScaleTick& tick : axisTicks(plane.lower.x, plane.upper.x)) {
    const float x = dataLeft + float(tick.position) * float(plane.width);
    render::drawLine(image, {x, y1}, {x, y1 + float(layout.mark)}, 1.0f, kInk);
    const int width = font.textWidth(tick.label, px);
    render::drawPlacedText(image,
                           render::placeText(tick.label, int(std::lround(x)) - width / 2,
                                             int(y1) + layout.mark + 4, px),
                           kInk, px);
  }
  for (const render::ScaleTick& tick : axisTicks(plane.lower.y, plane.upper.y)) {
    const float y = dataBottom - float(tick.position) * float(plane.height);
    render::drawLine(image, {x0 - float(layout.mark), y}, {x0, y}, 1.0f, kInk);
    const int width = font.textWidth(tick.label, px);
    render::drawPlacedText(image,
                           render::placeText(tick.label, int(x0) - layout.mark - 4 - width,
                                             int(std::lround(y)) - metrics.height() / 2, px),
                           kInk, px);
  }
  const std::array<std::string, 2> names = plane.axisNames();
  const std::string xName = axisName(names[0], unit), yName = axisName(names[1], unit);
  const int xWidth = font.textWidth(xName, px);
  render::drawPlacedText(image,
                         render::placeText(xName, layout.left + int(plane.width) / 2 - xWidth / 2,
                                           int(y1) + layout.mark + 6 + metrics.height() + 4, px),
                         kInk, px);
  render::drawPlacedText(image, render::placeText(yName, layout.left, 4, px), kInk, px);
}

}  // namespace

std::vector<float> stretchedLic(const std::vector<float>& lic) {
  double sum = 0.0, squares = 0.0;
  std::size_t count = 0;
  for (const float v : lic) {
    if (!std::isfinite(v)) continue;
    sum += v;
    squares += double(v) * v;
    ++count;
  }
  std::vector<float> stretched(lic.size(), std::numeric_limits<float>::quiet_NaN());
  if (count == 0) return stretched;
  const double mean = sum / double(count);
  const double spread = std::sqrt(std::max(squares / double(count) - mean * mean, 0.0));
  for (std::size_t n = 0; n < lic.size(); ++n) {
    if (!std::isfinite(lic[n])) continue;
    stretched[n] =
        spread > 0.0 ? float(std::clamp(0.5 + (lic[n] - mean) / (4.0 * spread), 0.0, 1.0)) : 0.5f;
  }
  return stretched;
}

FigureFrame sliceFigureFrame(const SlicePlane& plane, const SliceLayers& layers) {
  const Layout layout = layoutFigure(plane, layers);
  return {layout.left, layout.top};
}

render::Image drawSliceFigure(const SlicePlane& plane, const SliceLayers& layers) {
  const Layout layout = layoutFigure(plane, layers);
  Image image(layout.width, layout.height, kPaper);
  drawPixels(image, layout, plane, layers);
  drawLines(image, layout, plane, layers);
  drawAxes(image, layout, plane, layers.lengthUnit);
  for (const render::ColourBar& bar : colourBars(layers)) render::drawColourBar(image, bar);
  return image;
}

}  // namespace amrstream::slice
