#pragma once
// Rendering traces as tubes: how they look (radius, colour field and map, ambient occlusion),
// the context volume, the camera, the renderer's input made from traces, and an image rendered
// on a Vulkan device.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "amrstream/backend.hpp"
#include "amrstream/dataset.hpp"
#include "amrstream/log.hpp"
#include "flow/trace_set.hpp"
#include "flow/vector_volume.hpp"
#include "render/camera.hpp"
#include "render/image/colour_map.hpp"
#include "render/image/image.hpp"
#include "render/tube_geometry.hpp"
#include "render/tube_renderer.hpp"

namespace amrstream {

// Bounds of the options below: the image's sides in pixels, and the work per image, which is
// pixels x frames x (1 + ambient-occlusion rays): 4096 frames of 256 rays take hours on a fast
// GPU, and the image stops changing long before.
inline constexpr std::uint32_t kMinImageSide = 16, kMaxImageSide = 16384;
inline constexpr std::uint32_t kMaxRenderFrames = 4096;
inline constexpr std::uint32_t kMaxAoSamples = 256;

struct RenderOptions {
  std::uint32_t width = 1024, height = 768;
  std::vector<float> camera;        // azimuth, elevation (degrees)[, zoom]
  std::vector<double> viewBox;      // x0,y0,z0,x1,y1,z1 the camera frames; empty: the domain
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

// The renderer's input made from traces: tube segments, settings, colour map and camera.
struct RenderScene {
  std::vector<shared::TubeSegment> segments;
  render::RenderSettings settings;
  render::ColourMap colourMap = render::ColourMap::Viridis;
  std::string colourLabel;
  std::vector<float> contextScalars;    // brick-ordered; empty without --volume
  render::ChannelValues colourChannel;  // the --colour-by channel, when it is one
  render::OrbitCamera camera;
};

// Sets the tube radius and what depends on it (the ambient-occlusion ray length).
void setTubeRadius(render::RenderSettings& settings, float radius);

// Throws InputError for a bad colour map, colour field, volume channel, range, camera, image size,
// number of ambient-occlusion rays, or a value that is not finite.
// `cells` give the context volume's channel and scalars to colour by; `volume` the domain.
RenderScene prepareScene(const RenderOptions& o, const Dataset& cells,
                         const flow::VectorVolume& volume, const flow::TraceSet& traces);

// The tube segments and colour range for traces (also used as traces grow in the viewer).
void updateTubes(RenderScene& scene, const RenderOptions& o, const Dataset& cells,
                 const flow::VectorVolume& volume, const flow::TraceSet& traces);

// An image of traces: `frames` jittered samples per pixel accumulated, with the colour bar.
struct RenderedImage {
  render::Image image;
  std::string backend, device;
  std::size_t segments = 0;
  double setupSeconds = 0.0, renderSeconds = 0.0, kernelSecondsPerFrame = 0.0;
};
using FrameProgress = std::function<void(std::uint32_t done, std::uint32_t frames)>;

// Throws InputError when the request names the CPU backend: rendering needs a Vulkan device.
// (renderImage checks it too; callers that trace first check it before tracing.)
void requireRenderBackend(const BackendRequest& request);

// Throws InputError for the CPU backend (rendering needs a Vulkan device), bad options and frames
// outside 1..kMaxRenderFrames, vk::ContextError when the device lacks what the backend needs.
RenderedImage renderImage(const BackendRequest& request, const RenderOptions& options,
                          const Dataset& cells, const flow::VectorVolume& volume,
                          const flow::TraceSet& traces, std::uint32_t frames, bool colourBar,
                          const FrameProgress& progress = {}, const Log& log = {});

}  // namespace amrstream
