#include "scene_overlays.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "amrstream/error.hpp"
#include "render/annotations/axes.hpp"
#include "render/annotations/scale_bar.hpp"
#include "render/annotations/triad.hpp"
#include "render/image/colour_bar.hpp"
#include "render/image/colour_bar_layout.hpp"
#include "render/image/font.hpp"
#include "render/scene_space.hpp"

namespace amrstream {

glm::vec3 parseColour(const std::string& text, const char* option) {
  if (text == "white") return glm::vec3(1.0f);
  if (text == "black") return glm::vec3(0.0f);
  unsigned r = 0, g = 0, b = 0;
  char end = 0;
  if (text.size() == 7 && std::sscanf(text.c_str(), "#%2x%2x%2x%c", &r, &g, &b, &end) == 3)
    return glm::vec3(r, g, b) / 255.0f;
  float x = 0, y = 0, z = 0;
  if (std::sscanf(text.c_str(), "%f,%f,%f%c", &x, &y, &z, &end) == 3) {
    const glm::vec3 c(x, y, z);
    if (glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))) &&
        glm::all(glm::lessThanEqual(c, glm::vec3(1.0f))))
      return c;
  }
  throw settingError(option, fmt::format("'{}': give white, black, transparent, #rrggbb or R,G,B "
                                         "from 0 to 1",
                                         text));
}

namespace {

float luminance(glm::vec3 colour) { return glm::dot(colour, glm::vec3(0.2126f, 0.7152f, 0.0722f)); }

// The axes, triad and scale bar the options ask for, drawn over the rendered image in a grey
// that stands out from the background.
void drawAnnotations(render::Image& image, const RenderOptions& o, const RenderScene& scene,
                     const flow::VectorVolume& volume, const DatasetInfo& info) {
  const std::uint32_t w = image.width, h = image.height;
  const int size = render::overlayLabelPixelSize(w, h);
  const glm::vec3 grey = scene.settings.outlineColour * 1.15f;
  const render::Rgba8 ink = render::toRgba8(glm::min(grey, glm::vec3(1.0f)));
  if (o.axes) {
    const auto [lower, upper] = axesBounds(o, scene, volume);
    render::drawAxes(
        image,
        render::layoutAxes(scene.camera, w, h, lower, upper,
                           render::sceneTransformOf(volume.transform), size, shortLengthUnit(info)),
        ink);
  }
  if (o.triad) render::drawTriad(image, render::layoutTriad(scene.camera, w, h, size));
  if (o.scaleBar)
    render::drawScaleBar(
        image,
        render::layoutScaleBar(scene.camera, w, h, render::sceneUnitLength(volume.transform),
                               shortLengthUnit(info), size),
        ink);
}

// The context volume's colour bar, above the tubes': its transfer function's colours over its
// range (in log10 unless --linear-volume: then a log scale of the values).
render::ColourBar volumeBar(const RenderOptions& o, const RenderScene& scene) {
  const render::RenderSettings& s = scene.settings;
  render::ColourScale scale{render::ScaleKind::Linear, s.volumeRange.min, s.volumeRange.max};
  if (s.logVolume)
    scale = {render::ScaleKind::Log, std::pow(10.0, double(s.volumeRange.min)),
             std::pow(10.0, double(s.volumeRange.max))};
  return {render::ColourMap::Viridis,
          scale,
          o.volume + " (volume)",
          "",
          {shared::kVolumeLowColour, shared::kVolumeHighColour},
          1};
}

}  // namespace

glm::vec3 outlineColourOn(glm::vec3 background) {
  return luminance(background) > 0.5f ? glm::vec3(0.25f) : glm::vec3(0.75f);
}

std::vector<render::ColourBar> colourBarsOf(const RenderOptions& o, const RenderScene& scene) {
  const bool light = !scene.settings.transparent && luminance(scene.settings.background) > 0.5f;
  std::vector<render::ColourBar> bars{
      {scene.colourMap, scene.colourScale, scene.colourLabel, scene.colourUnit, {}, 0, light}};
  if (scene.settings.volume) {
    render::ColourBar bar = volumeBar(o, scene);
    bar.light = light;
    bars.push_back(bar);
  }
  return bars;
}

int colourBarsHeight(const RenderOptions& o, const RenderScene& scene, std::uint32_t width,
                     std::uint32_t height) {
  if (!o.colourBar) return 0;
  int top = int(height);
  for (const render::ColourBar& bar : colourBarsOf(o, scene))
    if (const auto layout = render::layoutColourBar(width, height, bar))
      top = std::min(top, layout->panel.y);
  return int(height) - top;
}

void drawOverlays(render::Image& image, const RenderOptions& o, const RenderScene& scene,
                  const flow::VectorVolume& volume, const DatasetInfo& info, bool colourBars) {
  drawAnnotations(image, o, scene, volume, info);
  if (!colourBars) return;
  for (const render::ColourBar& bar : colourBarsOf(o, scene)) render::drawColourBar(image, bar);
}

std::string shortLengthUnit(const DatasetInfo& info) {
  return info.lengthUnit.substr(0, info.lengthUnit.find(" ("));
}

}  // namespace amrstream
