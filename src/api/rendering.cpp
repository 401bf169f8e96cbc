#include "amrstream/rendering.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "render/image/colour_bar.hpp"
#include "render/volume_range.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

namespace {

// Half a finest cell, or wider on large domains so that a tube stays about a pixel wide in a
// 1024-pixel view of the whole domain.
float defaultTubeRadius(const flow::VectorVolume& volume) {
  const glm::vec3 extent = glm::vec3(volume.domain.upper - volume.domain.lower);
  return std::max(0.5f, glm::length(extent) / 1200.0f);
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
  if (!(o.volumeOpacity >= 0.0f) || !std::isfinite(o.volumeOpacity))
    throw InputError("--volume-opacity",
                     fmt::format("{} is not a finite number >= 0", o.volumeOpacity));
}

}  // namespace

void setTubeRadius(render::RenderSettings& settings, float radius) {
  settings.tubeRadius = radius;
  settings.aoDistance = 8.0f * radius;  // occluders within a few tube widths
}

void updateTubes(RenderScene& scene, const RenderOptions& o, const Dataset& cells,
                 const flow::VectorVolume& volume, const flow::TraceSet& traces) {
  const render::ColourField colour =
      render::colourFieldOf(traces, o.colourBy, cells, volume, scene.colourChannel);
  scene.segments = render::buildTubeSegments(traces, colour, volume.transform);
  scene.settings.colourRange =
      o.range.empty() ? render::rangeOf(colour.values) : parseRange(o.range, "--range");
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
  setTubeRadius(s, o.tubeRadius.value_or(defaultTubeRadius(volume)));
  if (!(s.tubeRadius > 0.0f) || !std::isfinite(s.tubeRadius))
    throw InputError("--tube-radius", "must be positive and finite");
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

  const float azimuth = o.camera.size() >= 2 ? o.camera[0] : 35.0f;
  const float elevation = o.camera.size() >= 2 ? o.camera[1] : 25.0f;
  const float zoom = o.camera.size() == 3 ? o.camera[2] : 1.0f;
  if (!(zoom > 0.0f)) throw InputError("--camera", "the zoom factor must be positive");
  glm::vec3 lower(volume.domain.lower), upper(volume.domain.upper);
  if (!o.viewBox.empty()) {
    if (o.viewBox.size() != 6)
      throw InputError("--view-box", "expected 6 numbers x0,y0,z0,x1,y1,z1");
    const glm::dvec3 a(o.viewBox[0], o.viewBox[1], o.viewBox[2]);
    const glm::dvec3 b(o.viewBox[3], o.viewBox[4], o.viewBox[5]);
    if (!glm::all(glm::lessThan(a, b)))
      throw InputError("--view-box", "the lower corner must be below the upper one on every axis");
    lower = glm::vec3(volume.transform.toCellUnits(a));
    upper = glm::vec3(volume.transform.toCellUnits(b));
  }
  scene.camera =
      render::frameBox(lower, upper, float(o.width) / float(o.height), azimuth, elevation, zoom);
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
  if (colourBar)
    render::drawColourBar(result.image, {scene.colourMap, scene.settings.colourRange.min,
                                         scene.settings.colourRange.max, scene.colourLabel});
  result.renderSeconds = clock.seconds();
  result.kernelSecondsPerFrame = kernelSeconds / frames;
  return result;
}

}  // namespace amrstream
