#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <span>
#include <utility>
#include <vector>

#include "amrstream/closest_name.hpp"
#include "amrstream/error.hpp"
#include "api/device.hpp"
#include "api/handles.hpp"
#include "api/job_state.hpp"
#include "api/render_scene.hpp"
#include "api/trace_memory.hpp"
#include "api/traces_impl.hpp"
#include "flow/seeds.hpp"
#include "render/image/font.hpp"
#include "render/image/png_io.hpp"
#include "render/scene_space.hpp"
#include "render/volume_range.hpp"
#include "scene_overlays.hpp"
#include "util/stopwatch.hpp"
#include "vk/aabb_scene.hpp"

namespace amrstream {

namespace {

// The tube radius in scene units (finest cells): --tube-radius, --tube-radius-physical, else a
// fraction of the view's height at the camera's target (so figures look alike whatever the data's
// depth).
float tubeRadiusOf(const RenderOptions& o, const flow::VectorVolume& volume,
                   const render::OrbitCamera& camera) {
  const int given = int(o.tubeRadius.has_value()) + int(o.tubeRadiusPhysical.has_value());
  if (given > 1)
    throw settingError("tube_radius", "give the radius in cells or in physical units, not both");
  float radius = 0.0f;
  const char* option = "tube_radius";
  if (o.tubeRadius) {
    radius = *o.tubeRadius;
  } else if (o.tubeRadiusPhysical) {
    const double sceneUnit = std::abs(render::sceneTransformOf(volume.transform).spacing.x);
    radius = float(*o.tubeRadiusPhysical / sceneUnit);
    option = "tube_radius_physical";
  } else {
    if (!(o.tubeRadiusOfView > 0.0f && o.tubeRadiusOfView <= 0.5f))
      throw settingError("tube_radius_view",
                         fmt::format("{} is outside (0, 0.5]", o.tubeRadiusOfView));
    radius = o.tubeRadiusOfView * 2.0f * camera.distance * render::halfHeightAtUnitDistance(camera);
    option = "tube_radius_view";
  }
  if (!(radius > 0.0f) || !std::isfinite(radius))
    throw settingError(option, "must be positive and finite");
  return radius;
}

render::ValueRange parseRange(const std::vector<float>& values, const char* option) {
  if (values.size() != 2 || !(values[0] < values[1]) || !std::isfinite(values[0]) ||
      !std::isfinite(values[1]))
    throw settingError(option, "expected finite MIN,MAX with MIN < MAX");
  return {values[0], values[1]};
}

template <class T>
void requireFinite(const std::vector<T>& values, const char* option) {
  for (const T value : values)
    if (!std::isfinite(value))
      throw settingError(option, fmt::format("{} is not a finite number", value));
}

// camera's azimuth and elevation (its zoom is checked where it frames the view).
void checkCameraAngles(const std::vector<float>& camera) {
  const std::pair<const char*, double> angles[] = {{"azimuth", settings::kMaxCameraAzimuth},
                                                   {"elevation", settings::kMaxCameraElevation}};
  for (std::size_t i = 0; i < std::min(camera.size(), std::size(angles)); ++i) {
    const auto [angle, most] = angles[i];
    if (!(std::abs(camera[i]) <= most))
      throw settingError("camera", fmt::format("{} {} is outside the range {} to {} degrees", angle,
                                               camera[i], -most, most));
  }
}

void checkImageOptions(const RenderOptions& o) {
  for (const auto& [side, option] : {std::pair{o.width, "width"}, std::pair{o.height, "height"}})
    if (side < kMinImageSide || side > kMaxImageSide)
      throw settingError(option, fmt::format("{} pixels is outside the range {} to {}", side,
                                             kMinImageSide, kMaxImageSide));
  if (o.aoSamples > kMaxAoSamples)
    throw settingError("ao_samples", fmt::format("{} rays per pixel and frame are more than {}",
                                                 o.aoSamples, kMaxAoSamples));
  requireFinite(o.camera, "camera");
  checkCameraAngles(o.camera);
  requireFinite(o.viewBox, "view_box");
  requireFinite(o.lookAt, "look_at");
  if (!(o.volumeOpacity >= 0.0f) || !std::isfinite(o.volumeOpacity))
    throw settingError("volume_opacity",
                       fmt::format("{} is not a finite number >= 0", o.volumeOpacity));
}

render::ScaleKind scaleKindOf(const RenderOptions& o) {
  const std::optional<render::ScaleKind> kind = render::parseScaleKind(o.colourScale);
  if (!kind)
    throw settingError("colour_scale",
                       fmt::format("no scale '{}'; choose linear, log or symlog", o.colourScale));
  return *kind;
}

// The colour field's scale: the kind asked for, over --range or the values seen (the positive
// values' for a log scale).
render::ColourScale colourScaleFor(const RenderOptions& o, render::ValueRange seen) {
  const std::optional<render::ValueRange> range =
      o.range.empty() ? std::nullopt : std::optional(parseRange(o.range, "range"));
  return colourScaleOver(scaleKindOf(o), range, seen, o.symlogWidth);
}

}  // namespace

render::ValueRange widenSeen(render::ValueRange seen, render::ScaleKind kind,
                             std::span<const float> values) {
  for (const float v : values)
    if (std::isfinite(v) && (kind != render::ScaleKind::Log || v > 0.0f))
      seen.min = std::min(seen.min, v), seen.max = std::max(seen.max, v);
  return seen;
}

render::ValueRange nothingSeen() { return {INFINITY, -INFINITY}; }

render::ColourScale colourScaleOver(render::ScaleKind kind,
                                    const std::optional<render::ValueRange>& range,
                                    render::ValueRange seen, std::optional<double> symlogWidth) {
  render::ColourScale scale;
  scale.kind = kind;
  if (range) {
    scale.min = range->min, scale.max = range->max;
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
    scale.linearWidth = symlogWidth.value_or(render::defaultLinearWidth(scale.min, scale.max));
  try {
    render::checkScale(scale);
  } catch (const std::invalid_argument& e) {
    throw settingError(range ? "range" : "colour_scale", e.what());
  }
  return scale;
}

namespace {

// The colour values as the tubes carry them: scale coordinates.
void toCoordinates(const render::ColourScale& scale, std::vector<float>& values) {
  if (scale.kind == render::ScaleKind::Linear) return;
  for (float& v : values)
    if (std::isfinite(v)) v = static_cast<float>(scale.coordinate(v));
}

// Grows scene.tracesBox to hold `segments`.
void widenTracesBox(RenderScene& scene, std::span<const shared::TubeSegment> segments) {
  for (const shared::TubeSegment& s : segments) {
    const glm::vec3 lower = glm::min(s.a, s.b), upper = glm::max(s.a, s.b);
    if (!scene.tracesBox) scene.tracesBox = std::pair{lower, upper};
    scene.tracesBox->first = glm::min(scene.tracesBox->first, lower);
    scene.tracesBox->second = glm::max(scene.tracesBox->second, upper);
  }
}

std::vector<shared::TubeSegment> outlineOf(const RenderOptions& o,
                                           const flow::VectorVolume& volume) {
  // auto: the axes' box, where it is not the domain, takes the domain outline's place.
  const bool axesAroundAnotherBox = o.axes && (o.frame == "traces" || !o.viewBox.empty());
  const std::string& outline = o.outline != "auto"    ? o.outline
                               : axesAroundAnotherBox ? "none"
                                                      : "domain";
  if (outline == "none") return {};
  const glm::vec3 scale(render::sceneScaleOf(volume.transform));
  if (outline == "domain")
    return render::boxOutline(glm::vec3(volume.domain.lower) * scale,
                              glm::vec3(volume.domain.upper) * scale);
  if (outline != "bricks")
    throw settingError("outline",
                       fmt::format("'{}': choose auto, domain, bricks or none", o.outline));
  std::vector<shared::TubeSegment> edges;
  for (std::size_t i = 0; i < volume.originalBrickCount; ++i) {
    const shared::Brick& brick = volume.bricks[i];
    const glm::vec3 lower(brick.lower);
    const glm::vec3 upper = lower + glm::vec3(brick.size) * std::ldexp(1.0f, brick.level);
    const std::vector<shared::TubeSegment> box = render::boxOutline(lower * scale, upper * scale);
    edges.insert(edges.end(), box.begin(), box.end());
  }
  return edges;
}

}  // namespace

void titleColourBar(RenderScene& scene, const RenderOptions& o, const flow::TraceSet& traces,
                    const DatasetInfo& info) {
  scene.colourLabel = o.colourBy == "speed"                         ? "|" + traces.vectorName + "|"
                      : o.colourBy == "time" && traces.timesAreAges ? "age"
                                                                    : o.colourBy;
  scene.colourUnit = o.colourBy == "time"    ? o.timeUnit
                     : o.colourBy == "speed" ? unitOf(info, traces.vectorName)
                                             : unitOf(info, o.colourBy);
}

void setColourRange(RenderScene& scene) {
  const render::ColourScale& scale = scene.colourScale;
  scene.settings.colourRange = {static_cast<float>(scale.coordinate(scale.min)),
                                static_cast<float>(scale.coordinate(scale.max))};
}

std::string integrationTimeUnit(flow::StepMode mode, const DatasetInfo& info) {
  return mode == flow::StepMode::Arc ? shortLengthUnit(info) : info.timeUnit;
}

void setTubeRadius(render::RenderSettings& settings, float radius) {
  settings.tubeRadius = radius;
  settings.aoDistance = 8.0f * radius;  // occluders within a few tube widths
}

void updateTubes(RenderScene& scene, const RenderOptions& o, const bricks::AmrField& cells,
                 const flow::VectorVolume& volume, const flow::TraceSet& traces) {
  render::ColourField colour =
      render::colourFieldOf(traces, o.colourBy, cells, volume, scene.colourChannel);
  scene.colourSeen = widenSeen(nothingSeen(), scaleKindOf(o), colour.values);
  scene.colourScale = colourScaleFor(o, scene.colourSeen);
  toCoordinates(scene.colourScale, colour.values);
  scene.segments =
      render::buildTubeSegments(traces, colour, render::sceneTransformOf(volume.transform));
  scene.tracesBox.reset();
  widenTracesBox(scene, scene.segments);
  scene.segments.insert(scene.segments.end(), scene.outline.begin(), scene.outline.end());
  setColourRange(scene);
}

std::optional<std::vector<shared::TubeSegment>> appendTubes(RenderScene& scene,
                                                            const RenderOptions& o,
                                                            const bricks::AmrField& cells,
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
      render::buildTubeSegments(recent, colour, render::sceneTransformOf(volume.transform));
  widenTracesBox(scene, added);
  scene.segments.insert(scene.segments.end() - std::ptrdiff_t(scene.outline.size()), added.begin(),
                        added.end());
  setColourRange(scene);
  return added;
}

RenderScene prepareScene(const RenderOptions& o, const bricks::AmrField& cells,
                         const flow::VectorVolume& volume, const flow::TraceSet& traces,
                         const DatasetInfo& info) {
  checkImageOptions(o);
  RenderScene scene;
  const auto map = render::parseColourMap(o.colourMap);
  if (!map)
    throw settingError("colour_map", fmt::format("no colour map '{}'; choose one of: {}",
                                                 o.colourMap, render::colourMapNames()));
  scene.colourMap = *map;
  titleColourBar(scene, o, traces, info);

  render::RenderSettings& s = scene.settings;
  if (o.background == "transparent") {
    s.transparent = true;
    s.outlineColour = glm::vec3(0.5f);  // whatever the image will be laid on
  } else {
    if (!o.background.empty()) {
      s.background = parseColour(o.background, "background");
      s.flatBackground = true;
    }
    s.outlineColour = outlineColourOn(s.background);
  }
  s.ambientOcclusion = o.aoSamples > 0;
  s.aoSamples = o.aoSamples;
  if (!(o.radiusByColour > 0.0f && o.radiusByColour <= 1.0f))
    throw settingError("radius_by_colour", fmt::format("{} is outside (0, 1]", o.radiusByColour));
  s.leastRadiusFraction = o.radiusByColour;
  updateTubes(scene, o, cells, volume, traces);

  if (!o.volume.empty()) {
    if (!cells.findChannel(o.volume)) {
      std::string choices;
      std::vector<std::string> candidates;
      for (const Channel& c : cells.channels()) {
        choices += (choices.empty() ? "" : ", ") + c.name;
        candidates.push_back(c.name);
      }
      throw settingError("volume", fmt::format("no channel '{}'{}; the input has: {}", o.volume,
                                               didYouMean(o.volume, candidates), choices));
    }
    scene.contextScalars = flow::gatherScalar(cells, volume, o.volume);
    s.volume = true;
    s.logVolume = !o.linearVolume;
    s.volumeRange = o.volumeRange.empty()
                        ? render::defaultVolumeRange(volume, scene.contextScalars, s.logVolume)
                        : parseRange(o.volumeRange, "volume_range");
    s.volumeOpacity = o.volumeOpacity > 0.0f
                          ? o.volumeOpacity
                          : render::defaultVolumeOpacity(volume, scene.contextScalars, s.logVolume,
                                                         s.volumeRange);
  }

  // Framed without the tubes' radius when the radius follows from the view: the margin holds it.
  if (o.tubeRadius && !(*o.tubeRadius > 0.0f && std::isfinite(*o.tubeRadius)))
    throw settingError("tube_radius", "must be positive and finite");
  setTubeRadius(s, o.tubeRadius.value_or(0.0f));
  frameCamera(scene, o, volume);
  setTubeRadius(s, tubeRadiusOf(o, volume, scene.camera));
  scene.outline = outlineOf(o, volume);
  scene.segments.insert(scene.segments.end(), scene.outline.begin(), scene.outline.end());
  return scene;
}

std::string colourMapNames() { return render::colourMapNames(); }

void requireRenderBackend(const BackendRequest& request) {
  if (request.backend == "cpu")
    throw settingError(
        "backend", "rendering needs a Vulkan device: choose auto, rayquery, pipeline or compute");
}

Image publicImage(render::Image image) {
  return {image.width, image.height, std::move(image.rgba)};
}

namespace {

// Host bytes a tube segment takes while the tubes are built: the scene's segment, its box and
// the renderer's copy in device order.
constexpr double kHostBytesPerSegment =
    2.0 * sizeof(shared::TubeSegment) + sizeof(VkAabbPositionsKHR);

// Tubes that the device's acceleration structures or this machine's memory cannot hold are
// refused before their segments are made. A line of n points is n - 1 segments, a lone point
// one (a sphere); each is a box of the structures that the ray tracing backends build.
void requireTubesFit(const vk::Context& ctx, gpu::Backend backend, const flow::TraceSet& lines) {
  std::uint64_t segments = 0;
  for (std::size_t line = 0; line < lines.lineCount(); ++line)
    segments += std::max<std::uint64_t>(lines.pointCount(line), 2) - 1;
  const std::uint64_t boxes = vk::maxBoxesPerScene(ctx);
  if (backend != gpu::Backend::Compute && segments > boxes)
    throw InputError("traces", fmt::format("{} tube segments are more than the {} that one "
                                           "acceleration structure of {} holds; render fewer "
                                           "lines or steps, or with {{backend}} compute",
                                           segments, boxes, ctx.deviceName()));
  const double bytes = double(segments) * kHostBytesPerSegment;
  const double limit = double(hostTraceLimit());
  if (limit > 0.0 && bytes > limit)
    throw InputError("traces", fmt::format("{} tube segments need {:.1f} GiB to build, more than "
                                           "the {:.1f} GiB this machine allows now; render fewer "
                                           "lines or steps",
                                           segments, bytes / 0x1p30, limit / 0x1p30));
}

// The dataset whose channels the tubes and the volume show.
const bricks::AmrField& renderedCells(const Field& field) {
  if (!field.dataset())
    throw std::logic_error("renderImage: the field was built without keeping its dataset");
  return cellsOf(*field.dataset());
}

}  // namespace

RenderedImage renderImage(const BackendRequest& request, const RenderOptions& options,
                          const Field& field, const Traces& traces, const Reporter& reporter) {
  const std::uint32_t frames = options.frames;
  const Log& log = reporter.log;
  requireRenderBackend(request);
  if (frames == 0 || frames > kMaxRenderFrames)
    throw settingError("frames",
                       fmt::format("{} is outside the range 1 to {}", frames, kMaxRenderFrames));
  const bricks::AmrField& cells = renderedCells(field);
  const flow::VectorVolume& volume = volumeOf(field);
  RenderOptions o = options;
  if (o.timeUnit.empty() && traces.impl().stepMode)
    o.timeUnit = integrationTimeUnit(*traces.impl().stepMode, field.info());
  if (o.colourBar || o.axes || o.triad || o.scaleBar)
    render::defaultFont();  // a missing font is told before the work, not after
  const BackendChoice choice = chooseBackend(request, BackendUse::Render, log);
  if (choice.backend == gpu::Backend::Cpu)
    throw vk::ContextError(
        "rendering needs a Vulkan device with compute; none was found "
        "(see `amrstream devices`)");
  const vk::Context ctx = createContext(request, choice);
  requireTubesFit(ctx, choice.backend, linesOf(traces));
  const RenderScene scene = prepareScene(o, cells, volume, linesOf(traces), field.info());
  RenderedImage result;
  result.backend = gpu::backendName(choice.backend);
  result.device = ctx.deviceName();
  result.segments = scene.segments.size();
  Stopwatch clock;
  render::TubeRenderer renderer(ctx, choice.backend, volume, scene.contextScalars);
  renderer.setTubes(scene.segments, scene.settings.tubeRadius);
  renderer.setColourMap(render::colourMapTable(scene.colourMap));
  renderer.resize(o.width, o.height);
  result.setupSeconds = clock.seconds();
  say(log, fmt::format("render     backend {} on {}: {} tube segments (radius {:g} cells), {} x "
                       "{}, {} frames [setup {:.2f} s]",
                       result.backend, result.device, scene.segments.size(),
                       scene.settings.tubeRadius, o.width, o.height, frames, result.setupSeconds));
  if (scene.settings.volume)
    say(log, fmt::format("volume     {}: {} {:.4g} to {:.4g}, opacity {:.3g} per finest cell{}",
                         o.volume, scene.settings.logVolume ? "log10" : "values",
                         scene.settings.volumeRange.min, scene.settings.volumeRange.max,
                         scene.settings.volumeOpacity,
                         o.volumeOpacity > 0.0f ? "" : " (from the histogram)"));
  clock.restart();
  double kernelSeconds = 0.0;
  for (std::uint32_t f = 0; f < frames; ++f) {
    renderer.renderFrame(scene.camera, scene.settings);
    kernelSeconds += renderer.lastFrameSeconds().value_or(0.0);
    reporter.advance("rendering", f + 1, frames);
  }
  checkValidation(ctx);
  render::Image image = renderer.readImage();
  drawOverlays(image, o, scene, volume, cells.info(), o.colourBar);
  result.image = publicImage(std::move(image));
  result.renderSeconds = clock.seconds();
  result.kernelSecondsPerFrame = kernelSeconds / frames;
  return result;
}

void writePng(const std::filesystem::path& path, const Image& image) {
  render::Image raster;
  raster.width = image.width;
  raster.height = image.height;
  raster.rgba = image.rgba;
  render::writePng(path, raster);
}

void checkTracesInDomain(const std::string& path, const Traces& traces, const Field& field,
                         const Log& log) {
  const flow::TraceSet& lines = linesOf(traces);
  const glm::dvec3 lower = field.lower(), upper = field.upper();
  const std::size_t points = lines.positions.size();
  std::size_t inside = 0;
  for (const glm::vec3& p : lines.positions) {
    const glm::dvec3 x(p);
    inside += glm::all(glm::greaterThanEqual(x, lower)) && glm::all(glm::lessThanEqual(x, upper));
  }
  say(log, fmt::format("traces     {} lines from {} ({} points)", withCommas(lines.lineCount()),
                       path, withCommas(points)));
  if (points > 0 && inside == 0)
    throw InputError(path, fmt::format("no trace point lies in the input's domain [{:g}, {:g}] x "
                                       "[{:g}, {:g}] x [{:g}, {:g}]; were they traced in another "
                                       "dataset?",
                                       lower.x, upper.x, lower.y, upper.y, lower.z, upper.z));
}

}  // namespace amrstream
