#include "render_options.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "render/volume_range.hpp"
#include "util/input_error.hpp"

namespace amrstream::cli {

namespace {

// Half a finest cell, or wider on large domains so that a tube stays about a pixel wide in a
// 1024-pixel view of the whole domain.
float defaultTubeRadius(const flow::VectorVolume& volume) {
  const glm::vec3 extent = glm::vec3(volume.domain.upper - volume.domain.lower);
  return std::max(0.5f, glm::length(extent) / 1200.0f);
}

render::ValueRange parseRange(const std::vector<float>& values, const char* option) {
  if (values.size() != 2 || !(values[0] < values[1]))
    throw InputError(option, "expected MIN,MAX with MIN < MAX");
  return {values[0], values[1]};
}

}  // namespace

void addRenderOptions(CLI::App& command, RenderOptions& o) {
  command.add_option("--width", o.width, "image width in pixels")->capture_default_str()->check(CLI::Range(16u, 16384u));
  command.add_option("--height", o.height, "image height in pixels")->capture_default_str()->check(CLI::Range(16u, 16384u));
  command.add_option("--camera", o.camera,
                     "AZIMUTH,ELEVATION[,ZOOM]: degrees about +z and above the xy plane, and a "
                     "zoom factor (> 1 closer) [default 35,25,1]")
      ->delimiter(',')
      ->expected(2, 3);
  command.add_option("--tube-radius", o.tubeRadius,
                     "tube radius in finest cells [default 0.5, or 1/1200 of the domain's "
                     "diagonal when larger]");
  command.add_option("--colour-by", o.colourBy,
                     "speed, time (IntegrationTime) or a scalar channel sampled along the tubes")
      ->capture_default_str();
  command.add_option("--colour-map", o.colourMap, "viridis, magma or coolwarm")->capture_default_str();
  command.add_option("--range", o.range, "MIN,MAX of the colour field [default: its range]")
      ->delimiter(',')
      ->expected(2);
  command.add_option("--ao-samples", o.aoSamples,
                     "ambient-occlusion rays per pixel and frame (0: off)")
      ->capture_default_str();
  command.add_option("--volume", o.volume,
                     "a scalar channel to show as a volume behind the tubes, e.g. dens");
  command.add_option("--volume-range", o.volumeRange,
                     "MIN,MAX of the transfer function, in log10 unless --linear-volume "
                     "[default: the median to the 99.9th percentile]")
      ->delimiter(',')
      ->expected(2);
  command.add_option("--volume-opacity", o.volumeOpacity,
                     "extinction per finest cell at the top of the transfer function")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  command.add_flag("--linear-volume", o.linearVolume,
                   "map the volume's scalar linearly instead of its log10");
}

void setTubeRadius(render::RenderSettings& settings, float radius) {
  settings.tubeRadius = radius;
  settings.aoDistance = 8.0f * radius;  // occluders within a few tube widths
}

void updateTubes(RenderScene& scene, const RenderOptions& o, const PreparedInput& input,
                 const flow::TraceSet& traces) {
  const render::ColourField colour =
      render::colourFieldOf(traces, o.colourBy, input.field(), input.volume, scene.colourChannel);
  scene.segments = render::buildTubeSegments(traces, colour, input.volume.transform);
  scene.settings.colourRange =
      o.range.empty() ? render::rangeOf(colour.values) : parseRange(o.range, "--range");
}

RenderScene prepareScene(const RenderOptions& o, const PreparedInput& input,
                         const flow::TraceSet& traces) {
  RenderScene scene;
  const auto map = render::parseColourMap(o.colourMap);
  if (!map)
    throw InputError("--colour-map", fmt::format("no colour map '{}'; choose one of: {}",
                                                 o.colourMap, render::colourMapNames()));
  scene.colourMap = *map;
  scene.colourLabel = o.colourBy == "speed" ? "|" + traces.vectorName + "|" : o.colourBy;

  render::RenderSettings& s = scene.settings;
  setTubeRadius(s, o.tubeRadius.value_or(defaultTubeRadius(input.volume)));
  if (!(s.tubeRadius > 0.0f)) throw InputError("--tube-radius", "must be positive");
  s.ambientOcclusion = o.aoSamples > 0;
  s.aoSamples = o.aoSamples;
  updateTubes(scene, o, input, traces);

  if (!o.volume.empty()) {
    if (!input.field().findChannel(o.volume)) {
      std::string choices;
      for (const bricks::Channel& c : input.field().channels())
        choices += (choices.empty() ? "" : ", ") + c.name;
      throw InputError("--volume", fmt::format("no channel '{}'; the input has: {}", o.volume, choices));
    }
    scene.contextScalars = flow::gatherScalar(input.field(), input.volume, o.volume);
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
  scene.camera = render::frameBox(glm::vec3(input.volume.domain.lower),
                                  glm::vec3(input.volume.domain.upper),
                                  float(o.width) / float(o.height), azimuth, elevation, zoom);
  return scene;
}

}  // namespace amrstream::cli
