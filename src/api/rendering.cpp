#include "amrstream/rendering.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <utility>

#include "render/image/colour_bar.hpp"
#include "render/image/font.hpp"
#include "render/annotations/axes.hpp"
#include "render/annotations/overlay_text.hpp"
#include "render/annotations/scale_bar.hpp"
#include "render/annotations/triad.hpp"
#include "render/volume_range.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

namespace {

// The tube radius in finest cells: --tube-radius, --tube-radius-physical, else a fraction of the
// view's height at the camera's target (so figures look alike whatever the data's depth).
float tubeRadiusOf(const RenderOptions& o, const flow::VectorVolume& volume,
                   const render::OrbitCamera& camera) {
  const int given = int(o.tubeRadius.has_value()) + int(o.tubeRadiusPhysical.has_value());
  if (given > 1)
    throw InputError("--tube-radius", "give the radius in cells or in physical units, not both");
  float radius = 0.0f;
  const char* option = "--tube-radius";
  if (o.tubeRadius) {
    radius = *o.tubeRadius;
  } else if (o.tubeRadiusPhysical) {
    const glm::dvec3 spacing = volume.transform.spacing;
    radius = float(*o.tubeRadiusPhysical / std::cbrt(spacing.x * spacing.y * spacing.z));
    option = "--tube-radius-physical";
  } else {
    if (!(o.tubeRadiusOfView > 0.0f && o.tubeRadiusOfView <= 0.5f))
      throw InputError("--tube-radius-view",
                       fmt::format("{} is outside (0, 0.5]", o.tubeRadiusOfView));
    radius = o.tubeRadiusOfView * 2.0f * camera.distance * render::halfHeightAtUnitDistance(camera);
    option = "--tube-radius-view";
  }
  if (!(radius > 0.0f) || !std::isfinite(radius))
    throw InputError(option, "must be positive and finite");
  return radius;
}

render::ValueRange parseRange(const std::vector<float>& values, const char* option) {
  if (values.size() != 2 || !(values[0] < values[1]) || !std::isfinite(values[0]) ||
      !std::isfinite(values[1]))
    throw InputError(option, "expected finite MIN,MAX with MIN < MAX");
  return {values[0], values[1]};
}

template <class T>
void requireFinite(const std::vector<T>& values, const char* option) {
  for (const T value : values)
    if (!std::isfinite(value))
      throw InputError(option, fmt::format("{} is not a finite number", value));
}

void checkImageOptions(const RenderOptions& o) {
  for (const auto& [side, option] :
       {std::pair{o.width, "--width"}, std::pair{o.height, "--height"}})
    if (side < kMinImageSide || side > kMaxImageSide)
      throw InputError(option, fmt::format("{} pixels is outside the range {} to {}", side,
                                           kMinImageSide, kMaxImageSide));
  if (o.aoSamples > kMaxAoSamples)
    throw InputError("--ao-samples", fmt::format("{} rays per pixel and frame are more than {}",
                                                 o.aoSamples, kMaxAoSamples));
  requireFinite(o.camera, "--camera");
  requireFinite(o.viewBox, "--view-box");
  requireFinite(o.lookAt, "--look-at");
  if (!(o.volumeOpacity >= 0.0f) || !std::isfinite(o.volumeOpacity))
    throw InputError("--volume-opacity",
                     fmt::format("{} is not a finite number >= 0", o.volumeOpacity));
}

// The colour field's scale: the kind asked for, over --range or the values' own range (the
// positive values' for a log scale).
render::ColourScale colourScaleFor(const RenderOptions& o, std::span<const float> values) {
  const std::optional<render::ScaleKind> kind = render::parseScaleKind(o.colourScale);
  if (!kind)
    throw InputError("--colour-scale",
                     fmt::format("no scale '{}'; choose linear, log or symlog", o.colourScale));
  render::ColourScale scale;
  scale.kind = *kind;
  if (!o.range.empty()) {
    const render::ValueRange range = parseRange(o.range, "--range");
    scale.min = range.min, scale.max = range.max;
  } else {
    double lo = INFINITY, hi = -INFINITY;
    for (const float v : values)
      if (std::isfinite(v) && (*kind != render::ScaleKind::Log || v > 0.0f))
        lo = std::min(lo, double(v)), hi = std::max(hi, double(v));
    if (lo > hi) lo = *kind == render::ScaleKind::Log ? 1.0 : 0.0, hi = lo;  // nothing to show
    if (!(lo < hi)) {  // one value: a range around it
      const double pad = lo != 0.0 ? std::abs(lo) * 0.5 : 1.0;
      hi = lo + pad, lo = *kind == render::ScaleKind::Log ? lo * 0.5 : lo - pad;
    }
    scale.min = lo, scale.max = hi;
  }
  if (*kind == render::ScaleKind::SymLog)
    scale.linearWidth = o.symlogWidth.value_or(render::defaultLinearWidth(scale.min, scale.max));
  try {
    render::checkScale(scale);
  } catch (const std::invalid_argument& e) {
    throw InputError(o.range.empty() ? "--colour-scale" : "--range", e.what());
  }
  return scale;
}

// What the camera frames, in cell units: the corners of --view-box, else the tubes' ends (with
// their radius) or the domain's corners.
struct Framed {
  std::vector<glm::vec3> points;
  float radius = 0.0f;
};

std::vector<glm::vec3> boxCorners(glm::vec3 lower, glm::vec3 upper) {
  std::vector<glm::vec3> corners;
  for (int corner = 0; corner < 8; ++corner)
    corners.push_back({(corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                       (corner & 4) ? upper.z : lower.z});
  return corners;
}

// --view-box in cell units, checked; nullopt without one.
std::optional<std::pair<glm::vec3, glm::vec3>> viewBoxOf(const RenderOptions& o,
                                                         const flow::VectorVolume& volume) {
  if (o.viewBox.empty()) return std::nullopt;
  if (o.viewBox.size() != 6) throw InputError("--view-box", "expected 6 numbers x0,y0,z0,x1,y1,z1");
  const glm::dvec3 a(o.viewBox[0], o.viewBox[1], o.viewBox[2]);
  const glm::dvec3 b(o.viewBox[3], o.viewBox[4], o.viewBox[5]);
  if (!glm::all(glm::lessThan(a, b)))
    throw InputError("--view-box", "the lower corner must be below the upper one on every axis");
  return std::pair{glm::vec3(volume.transform.toCellUnits(a)),
                   glm::vec3(volume.transform.toCellUnits(b))};
}

// The box --axes follows, in cell units: --view-box, else the domain.
std::pair<glm::vec3, glm::vec3> axesBox(const RenderOptions& o, const flow::VectorVolume& volume) {
  return viewBoxOf(o, volume).value_or(
      std::pair{glm::vec3(volume.domain.lower), glm::vec3(volume.domain.upper)});
}

Framed framedPoints(const RenderOptions& o, const flow::VectorVolume& volume,
                    std::span<const shared::TubeSegment> segments, float radius) {
  if (const auto box = viewBoxOf(o, volume)) return {boxCorners(box->first, box->second)};
  if (o.frame != "traces" && o.frame != "domain")
    throw InputError("--frame", fmt::format("'{}': choose traces or domain", o.frame));
  if (o.frame == "traces" && !segments.empty()) {
    Framed framed{{}, radius};
    framed.points.reserve(2 * segments.size() + 8);
    for (const shared::TubeSegment& s : segments) {
      framed.points.push_back(s.a);
      framed.points.push_back(s.b);
    }
    if (o.axes) {  // the axes (on the domain) and their labels stay in view too
      const auto [lower, upper] = axesBox(o, volume);
      const std::vector<glm::vec3> corners = boxCorners(lower, upper);
      framed.points.insert(framed.points.end(), corners.begin(), corners.end());
    }
    return framed;
  }
  return {boxCorners(glm::vec3(volume.domain.lower), glm::vec3(volume.domain.upper))};
}

// The camera the options ask for, before framing.
render::OrbitCamera cameraOf(const RenderOptions& o) {
  render::OrbitCamera camera;
  const std::optional<render::Axis> up = render::parseAxis(o.up);
  if (!up) throw InputError("--up", fmt::format("'{}': choose +x, -x, +y, -y, +z or -z", o.up));
  camera.up = *up;
  if (!(o.fovDegrees >= 1.0f && o.fovDegrees <= 150.0f))
    throw InputError("--fov", fmt::format("{} degrees is outside 1 to 150", o.fovDegrees));
  camera.fovYDegrees = o.fovDegrees;
  if (o.projection == "orthographic")
    camera.projection = render::Projection::Orthographic;
  else if (o.projection != "perspective")
    throw InputError("--projection",
                     fmt::format("'{}': choose perspective or orthographic", o.projection));
  if (!o.view.empty()) {
    if (!o.camera.empty())
      throw InputError("--view", "give either --view or --camera's azimuth and elevation");
    const std::optional<render::NamedView> view = render::namedView(o.view, camera.up);
    if (!view)
      throw InputError("--view", fmt::format("no view '{}'; choose one of: {}", o.view,
                                             render::namedViewNames()));
    camera.azimuthDegrees = view->azimuthDegrees;
    camera.elevationDegrees = view->elevationDegrees;
  } else if (o.camera.size() >= 2) {
    camera.azimuthDegrees = o.camera[0];
    camera.elevationDegrees = std::clamp(o.camera[1], -90.0f, 90.0f);
  }
  return camera;
}

// The traces' tubes: the scene's segments before the outline's.
std::span<const shared::TubeSegment> traceSegments(const RenderScene& scene) {
  return std::span(scene.segments).first(scene.segments.size() - scene.outline.size());
}

std::vector<shared::TubeSegment> outlineOf(const RenderOptions& o,
                                           const flow::VectorVolume& volume) {
  if (o.outline == "none") return {};
  if (o.outline == "domain")
    return render::boxOutline(glm::vec3(volume.domain.lower), glm::vec3(volume.domain.upper));
  if (o.outline != "bricks")
    throw InputError("--outline", fmt::format("'{}': choose domain, bricks or none", o.outline));
  std::vector<shared::TubeSegment> edges;
  for (std::size_t i = 0; i < volume.originalBrickCount; ++i) {
    const shared::Brick& brick = volume.bricks[i];
    const glm::vec3 lower(brick.lower);
    const std::vector<shared::TubeSegment> box =
        render::boxOutline(lower, lower + glm::vec3(brick.size) * std::ldexp(1.0f, brick.level));
    edges.insert(edges.end(), box.begin(), box.end());
  }
  return edges;
}

// A colour as --background takes it: a name, #rrggbb, or R,G,B in [0, 1].
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
  throw InputError(option, fmt::format("'{}': give white, black, transparent, #rrggbb or R,G,B "
                                       "from 0 to 1",
                                       text));
}

float luminance(glm::vec3 colour) { return glm::dot(colour, glm::vec3(0.2126f, 0.7152f, 0.0722f)); }

// Outlines stand out from the background: dark on light, light on dark.
glm::vec3 outlineColourOn(glm::vec3 background) {
  return luminance(background) > 0.5f ? glm::vec3(0.25f) : glm::vec3(0.75f);
}

// The axes, triad and scale bar the options ask for, drawn over the rendered image in a grey
// that stands out from the background.
void drawAnnotations(render::Image& image, const RenderOptions& o, const RenderScene& scene,
                     const flow::VectorVolume& volume, const bricks::DatasetInfo& info) {
  const std::uint32_t w = image.width, h = image.height;
  const int size = render::overlayLabelPixelSize(w, h);
  const glm::vec3 grey = scene.settings.outlineColour * 1.15f;
  const render::Rgba8 ink = render::toRgba8(glm::min(grey, glm::vec3(1.0f)));
  if (o.axes) {
    const auto [lower, upper] = axesBounds(o, volume);
    render::drawAxes(image,
                     render::layoutAxes(scene.camera, w, h, lower, upper, volume.transform, size),
                     ink);
  }
  if (o.triad) render::drawTriad(image, render::layoutTriad(scene.camera, w, h, size));
  if (o.scaleBar)
    render::drawScaleBar(image,
                         render::layoutScaleBar(scene.camera, w, h, volume.transform,
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
  return {render::ColourMap::Viridis, scale, o.volume + " (volume)", "",
          {shared::kVolumeLowColour, shared::kVolumeHighColour}, 1};
}

}  // namespace

std::pair<glm::dvec3, glm::dvec3> axesBounds(const RenderOptions& o,
                                             const flow::VectorVolume& volume) {
  const auto [lower, upper] = axesBox(o, volume);
  return {volume.transform.toPhysical(glm::dvec3(lower)),
          volume.transform.toPhysical(glm::dvec3(upper))};
}

std::string shortLengthUnit(const bricks::DatasetInfo& info) {
  return info.lengthUnit.substr(0, info.lengthUnit.find(" ("));
}

void setTubeRadius(render::RenderSettings& settings, float radius) {
  settings.tubeRadius = radius;
  settings.aoDistance = 8.0f * radius;  // occluders within a few tube widths
}

void updateTubes(RenderScene& scene, const RenderOptions& o, const Dataset& cells,
                 const flow::VectorVolume& volume, const flow::TraceSet& traces) {
  render::ColourField colour =
      render::colourFieldOf(traces, o.colourBy, cells, volume, scene.colourChannel);
  scene.colourScale = colourScaleFor(o, colour.values);
  const render::ColourScale& scale = scene.colourScale;
  if (scale.kind != render::ScaleKind::Linear)
    for (float& v : colour.values)
      if (std::isfinite(v)) v = static_cast<float>(scale.coordinate(v));
  scene.segments = render::buildTubeSegments(traces, colour, volume.transform);
  scene.segments.insert(scene.segments.end(), scene.outline.begin(), scene.outline.end());
  scene.settings.colourRange = {static_cast<float>(scale.coordinate(scale.min)),
                                static_cast<float>(scale.coordinate(scale.max))};
}

void frameCamera(RenderScene& scene, const RenderOptions& o, const flow::VectorVolume& volume) {
  // Axes need room outside the framed box for their labels.
  const float zoom = o.zoom * (o.camera.size() == 3 ? o.camera[2] : 1.0f) * (o.axes ? 0.8f : 1.0f);
  if (!(zoom > 0.0f) || !std::isfinite(zoom))
    throw InputError(o.camera.size() == 3 ? "--camera" : "--zoom",
                     "the zoom factor must be positive and finite");
  const Framed framed = framedPoints(o, volume, traceSegments(scene), scene.settings.tubeRadius);
  std::optional<glm::vec3> target;
  if (!o.lookAt.empty()) {
    if (o.lookAt.size() != 3) throw InputError("--look-at", "expected 3 numbers x,y,z");
    target = glm::vec3(
        volume.transform.toCellUnits(glm::dvec3(o.lookAt[0], o.lookAt[1], o.lookAt[2])));
  }
  scene.camera = render::framePoints(cameraOf(o), framed.points, framed.radius,
                                     float(o.width) / float(o.height), zoom, target);
}

void frameTubes(RenderScene& scene, const flow::VectorVolume& volume, float aspect) {
  RenderOptions tubes;
  tubes.frame = "traces";
  const Framed framed =
      framedPoints(tubes, volume, traceSegments(scene), scene.settings.tubeRadius);
  scene.camera = render::framePoints(scene.camera, framed.points, framed.radius, aspect);
}

RenderScene prepareScene(const RenderOptions& o, const Dataset& cells,
                         const flow::VectorVolume& volume, const flow::TraceSet& traces) {
  checkImageOptions(o);
  RenderScene scene;
  const auto map = render::parseColourMap(o.colourMap);
  if (!map)
    throw InputError("--colour-map", fmt::format("no colour map '{}'; choose one of: {}",
                                                 o.colourMap, render::colourMapNames()));
  scene.colourMap = *map;
  scene.colourLabel = o.colourBy == "speed" ? "|" + traces.vectorName + "|" : o.colourBy;

  render::RenderSettings& s = scene.settings;
  if (o.background == "transparent") {
    s.transparent = true;
    s.outlineColour = glm::vec3(0.5f);  // whatever the image will be laid on
  } else {
    if (!o.background.empty()) {
      s.background = parseColour(o.background, "--background");
      s.flatBackground = true;
    }
    s.outlineColour = outlineColourOn(s.background);
  }
  s.ambientOcclusion = o.aoSamples > 0;
  s.aoSamples = o.aoSamples;
  updateTubes(scene, o, cells, volume, traces);

  if (!o.volume.empty()) {
    if (!cells.findChannel(o.volume)) {
      std::string choices;
      for (const bricks::Channel& c : cells.channels())
        choices += (choices.empty() ? "" : ", ") + c.name;
      throw InputError("--volume",
                       fmt::format("no channel '{}'; the input has: {}", o.volume, choices));
    }
    scene.contextScalars = flow::gatherScalar(cells, volume, o.volume);
    s.volume = true;
    s.logVolume = !o.linearVolume;
    s.volumeRange = o.volumeRange.empty()
                        ? render::defaultVolumeRange(scene.contextScalars, s.logVolume)
                        : parseRange(o.volumeRange, "--volume-range");
    s.volumeOpacity = o.volumeOpacity;
  }

  // Framed without the tubes' radius when the radius follows from the view: the margin holds it.
  if (o.tubeRadius && !(*o.tubeRadius > 0.0f && std::isfinite(*o.tubeRadius)))
    throw InputError("--tube-radius", "must be positive and finite");
  setTubeRadius(s, o.tubeRadius.value_or(0.0f));
  frameCamera(scene, o, volume);
  setTubeRadius(s, tubeRadiusOf(o, volume, scene.camera));
  scene.outline = outlineOf(o, volume);
  scene.segments.insert(scene.segments.end(), scene.outline.begin(), scene.outline.end());
  return scene;
}

void requireRenderBackend(const BackendRequest& request) {
  if (request.backend == "cpu")
    throw InputError("--backend",
                     "rendering needs a Vulkan device: choose auto, rayquery, pipeline or compute");
}

RenderedImage renderImage(const BackendRequest& request, const RenderOptions& options,
                          const Dataset& cells, const flow::VectorVolume& volume,
                          const flow::TraceSet& traces, std::uint32_t frames, bool colourBar,
                          const FrameProgress& progress, const Log& log) {
  requireRenderBackend(request);
  if (frames == 0 || frames > kMaxRenderFrames)
    throw InputError("--frames", fmt::format("{} is outside the range 1 to {}", frames,
                                             kMaxRenderFrames));
  const RenderScene scene = prepareScene(options, cells, volume, traces);
  if (colourBar || options.axes || options.triad || options.scaleBar)
    render::defaultFont();  // a missing font is told before the work, not after
  const BackendChoice choice = chooseBackend(request, BackendUse::Render, log);
  if (choice.backend == gpu::Backend::Cpu)
    throw vk::ContextError(
        "rendering needs a Vulkan device with compute; none was found "
        "(see `amrstream devices`)");
  const vk::Context ctx = createContext(request, choice);
  RenderedImage result;
  result.backend = gpu::backendName(choice.backend);
  result.device = ctx.deviceName();
  result.segments = scene.segments.size();
  Stopwatch clock;
  render::TubeRenderer renderer(ctx, choice.backend, volume, scene.contextScalars);
  renderer.setTubes(scene.segments, scene.settings.tubeRadius);
  renderer.setColourMap(render::colourMapTable(scene.colourMap));
  renderer.resize(options.width, options.height);
  result.setupSeconds = clock.seconds();
  say(log,
      fmt::format("render     backend {} on {}: {} tube segments (radius {:g} cells), {} x "
                  "{}, {} frames [setup {:.2f} s]",
                  result.backend, result.device, scene.segments.size(), scene.settings.tubeRadius,
                  options.width, options.height, frames, result.setupSeconds));
  clock.restart();
  double kernelSeconds = 0.0;
  for (std::uint32_t f = 0; f < frames; ++f) {
    renderer.renderFrame(scene.camera, scene.settings);
    kernelSeconds += renderer.lastFrameSeconds().value_or(0.0);
    if (progress) progress(f + 1, frames);
  }
  checkValidation(ctx);
  result.image = renderer.readImage();
  drawAnnotations(result.image, options, scene, volume, cells.info());
  if (colourBar) {
    const bool light = !scene.settings.transparent && luminance(scene.settings.background) > 0.5f;
    render::drawColourBar(result.image, {scene.colourMap, scene.colourScale, scene.colourLabel,
                                         "", {}, 0, light});
    if (scene.settings.volume) {
      render::ColourBar volume = volumeBar(options, scene);
      volume.light = light;
      render::drawColourBar(result.image, volume);
    }
  }
  result.renderSeconds = clock.seconds();
  result.kernelSecondsPerFrame = kernelSeconds / frames;
  return result;
}

}  // namespace amrstream
