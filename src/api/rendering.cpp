#include "amrstream/rendering.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "render/image/font.hpp"
#include "render/volume_range.hpp"
#include "scene_overlays.hpp"
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

render::ScaleKind scaleKindOf(const RenderOptions& o) {
  const std::optional<render::ScaleKind> kind = render::parseScaleKind(o.colourScale);
  if (!kind)
    throw InputError("--colour-scale",
                     fmt::format("no scale '{}'; choose linear, log or symlog", o.colourScale));
  return *kind;
}

// The finite values the scale can show (positive ones for log), grown by `values`.
render::ValueRange widenSeen(render::ValueRange seen, render::ScaleKind kind,
                             std::span<const float> values) {
  for (const float v : values)
    if (std::isfinite(v) && (kind != render::ScaleKind::Log || v > 0.0f))
      seen.min = std::min(seen.min, v), seen.max = std::max(seen.max, v);
  return seen;
}

render::ValueRange nothingSeen() { return {INFINITY, -INFINITY}; }

// The colour field's scale: the kind asked for, over --range or the values seen (the positive
// values' for a log scale).
render::ColourScale colourScaleFor(const RenderOptions& o, render::ValueRange seen) {
  const render::ScaleKind kind = scaleKindOf(o);
  render::ColourScale scale;
  scale.kind = kind;
  if (!o.range.empty()) {
    const render::ValueRange range = parseRange(o.range, "--range");
    scale.min = range.min, scale.max = range.max;
  } else {
    double lo = seen.min, hi = seen.max;
    if (lo > hi) lo = kind == render::ScaleKind::Log ? 1.0 : 0.0, hi = lo;  // nothing to show
    if (!(lo < hi)) {  // one value: a range around it
      const double pad = lo != 0.0 ? std::abs(lo) * 0.5 : 1.0;
      hi = lo + pad, lo = kind == render::ScaleKind::Log ? lo * 0.5 : lo - pad;
    }
    scale.min = lo, scale.max = hi;
  }
  if (kind == render::ScaleKind::SymLog)
    scale.linearWidth = o.symlogWidth.value_or(render::defaultLinearWidth(scale.min, scale.max));
  try {
    render::checkScale(scale);
  } catch (const std::invalid_argument& e) {
    throw InputError(o.range.empty() ? "--colour-scale" : "--range", e.what());
  }
  return scale;
}

// The colour values as the tubes carry them: scale coordinates.
void toCoordinates(const render::ColourScale& scale, std::vector<float>& values) {
  if (scale.kind == render::ScaleKind::Linear) return;
  for (float& v : values)
    if (std::isfinite(v)) v = static_cast<float>(scale.coordinate(v));
}

void setColourRange(RenderScene& scene) {
  const render::ColourScale& scale = scene.colourScale;
  scene.settings.colourRange = {static_cast<float>(scale.coordinate(scale.min)),
                                static_cast<float>(scale.coordinate(scale.max))};
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

}  // namespace

std::string integrationTimeUnit(flow::StepMode mode, const bricks::DatasetInfo& info) {
  return mode == flow::StepMode::Arc ? shortLengthUnit(info) : info.timeUnit;
}

void setTubeRadius(render::RenderSettings& settings, float radius) {
  settings.tubeRadius = radius;
  settings.aoDistance = 8.0f * radius;  // occluders within a few tube widths
}

void updateTubes(RenderScene& scene, const RenderOptions& o, const Dataset& cells,
                 const flow::VectorVolume& volume, const flow::TraceSet& traces) {
  render::ColourField colour =
      render::colourFieldOf(traces, o.colourBy, cells, volume, scene.colourChannel);
  scene.colourSeen = widenSeen(nothingSeen(), scaleKindOf(o), colour.values);
  scene.colourScale = colourScaleFor(o, scene.colourSeen);
  toCoordinates(scene.colourScale, colour.values);
  scene.segments = render::buildTubeSegments(traces, colour, volume.transform);
  scene.segments.insert(scene.segments.end(), scene.outline.begin(), scene.outline.end());
  setColourRange(scene);
}

std::optional<std::vector<shared::TubeSegment>> appendTubes(RenderScene& scene,
                                                            const RenderOptions& o,
                                                            const Dataset& cells,
                                                            const flow::VectorVolume& volume,
                                                            const flow::TraceSet& recent) {
  render::ColourField colour =
      render::colourFieldOf(recent, o.colourBy, cells, volume, scene.colourChannel);
  const render::ValueRange seen = widenSeen(scene.colourSeen, scaleKindOf(o), colour.values);
  const render::ColourScale scale = colourScaleFor(o, seen);
  // The coordinates of a symmetric-log scale depend on its width, which follows the range.
  if (scale.kind == render::ScaleKind::SymLog && scale.linearWidth != scene.colourScale.linearWidth)
    return std::nullopt;
  scene.colourSeen = seen;
  scene.colourScale = scale;
  toCoordinates(scale, colour.values);
  std::vector<shared::TubeSegment> added =
      render::buildTubeSegments(recent, colour, volume.transform);
  scene.segments.insert(scene.segments.end() - std::ptrdiff_t(scene.outline.size()), added.begin(),
                        added.end());
  setColourRange(scene);
  return added;
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
  scene.colourUnit = o.colourBy == "time" ? o.timeUnit : std::string();

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
  if (!(o.radiusByColour > 0.0f && o.radiusByColour <= 1.0f))
    throw InputError("--radius-by-colour", fmt::format("{} is outside (0, 1]", o.radiusByColour));
  s.leastRadiusFraction = o.radiusByColour;
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
    throw InputError("--frames",
                     fmt::format("{} is outside the range 1 to {}", frames, kMaxRenderFrames));
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
  drawOverlays(result.image, options, scene, volume, cells.info(), colourBar);
  result.renderSeconds = clock.seconds();
  result.kernelSecondsPerFrame = kernelSeconds / frames;
  return result;
}

}  // namespace amrstream
