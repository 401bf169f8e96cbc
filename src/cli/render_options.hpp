#pragma once
// What `render` and `view` share: how the tubes look (radius, colour field and map, ambient
// occlusion), the context volume, the camera, and turning traces into the renderer's input.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/image/colour_map.hpp"
#include "render/tube_geometry.hpp"
#include "render/tube_renderer.hpp"
#include "trace_job.hpp"

namespace amrstream::cli {

struct RenderOptions {
  std::uint32_t width = 1024, height = 768;
  std::vector<float> camera;  // azimuth, elevation (degrees)[, zoom]
  std::optional<float> tubeRadius;  // finest cells
  std::string colourBy = "speed";
  std::string colourMap = "viridis";
  std::vector<float> range;  // min, max of the colour field
  std::uint32_t aoSamples = 4;
  std::string volume;  // context scalar channel; empty: none
  std::vector<float> volumeRange;
  float volumeOpacity = 0.05f;
  bool linearVolume = false;
};

// Adds the options above to `command`.
void addRenderOptions(CLI::App& command, RenderOptions& options);

// The renderer's input made from traces: tube segments, settings, colour map and camera.
struct RenderScene {
  std::vector<shared::TubeSegment> segments;
  render::RenderSettings settings;
  render::ColourMap colourMap = render::ColourMap::Viridis;
  std::string colourLabel;
  std::vector<float> contextScalars;  // brick-ordered; empty without --volume
  render::ChannelValues colourChannel;  // the --colour-by channel, when it is one
  render::OrbitCamera camera;
};

// Sets the tube radius and what depends on it (the ambient-occlusion ray length).
void setTubeRadius(render::RenderSettings& settings, float radius);

// Throws InputError for a bad colour map, colour field, volume channel, range or camera.
RenderScene prepareScene(const RenderOptions& o, const PreparedInput& input,
                         const flow::TraceSet& traces);

// The tube segments and colour range for traces (also used as traces grow in the viewer).
void updateTubes(RenderScene& scene, const RenderOptions& o, const PreparedInput& input,
                 const flow::TraceSet& traces);

}  // namespace amrstream::cli
