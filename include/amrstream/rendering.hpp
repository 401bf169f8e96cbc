#pragma once
// Rendering traces as tubes: how they look (radius, colour field and map, ambient occlusion),
// the context volume, the camera, the renderer's input made from traces, and an image rendered
// on a Vulkan device.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "amrstream/backend.hpp"
#include "amrstream/dataset.hpp"
#include "amrstream/log.hpp"
#include "flow/trace_options.hpp"
#include "flow/trace_set.hpp"
#include "flow/vector_volume.hpp"
#include "render/camera.hpp"
#include "render/image/colour_map.hpp"
#include "render/image/colour_scale.hpp"
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
  std::vector<float> camera;  // azimuth, elevation (degrees)[, zoom]
  std::string view;           // a named view (render::namedView); empty: --camera's or 35, 25
  float zoom = 1.0f;          // > 1 closer; --camera's third number multiplies it
  std::string up = "+z";      // the axis up on screen
  float fovDegrees = 35.0f;   // vertical field of view (and an orthographic view's height)
  std::string projection = "perspective";  // or "orthographic"
  std::string frame = "traces";            // what the camera frames: "traces" or "domain"
  std::vector<double> lookAt;       // x,y,z the camera looks at; empty: the framed box's centre
  std::vector<double> viewBox;      // x0,y0,z0,x1,y1,z1 the camera frames; empty: see `frame`
  std::optional<float> tubeRadius;  // finest cells
  std::optional<double> tubeRadiusPhysical;  // the input's length units
  float tubeRadiusOfView = 0.003f;           // without either: a fraction of the view's height
  // Below 1: tubes as thick as the colour field is high, from this fraction of the radius at the
  // colour range's low end to the whole radius at its high end (in the colour scale's terms).
  float radiusByColour = 1.0f;
  std::string colourBy = "speed";
  std::string timeUnit;  // IntegrationTime's unit, on the colour bar of --colour-by time; "": none
  std::string colourMap = "viridis";
  std::string colourScale = "linear";  // "log" or "symlog"
  std::optional<double> symlogWidth;   // symlog's linear half-width; default 1e-3 of the range
  std::vector<float> range;            // min, max of the colour field
  std::string outline = "domain";      // thin grey tubes along "domain", "bricks" or "none"
  bool axes = false;       // the domain's axes with ticks in physical units (zooms out a little)
  bool triad = true;       // the orientation triad, bottom left
  bool scaleBar = false;   // a bar of a round physical length above the triad
  std::string background;  // "white", "black", "#rrggbb" or "R,G,B" (0..1): flat
  std::uint32_t aoSamples = 4;
  std::string volume;  // context scalar channel; empty: none
  std::vector<float> volumeRange;
  float volumeOpacity = 0.05f;
  bool linearVolume = false;
};

// The renderer's input made from traces: tube segments, settings, colour map and camera.
struct RenderScene {
  // The traces' tubes, then the outline's (RenderOptions::outline), which updateTubes keeps.
  std::vector<shared::TubeSegment> segments;
  std::vector<shared::TubeSegment> outline;
  render::RenderSettings settings;
  render::ColourMap colourMap = render::ColourMap::Viridis;
  // The colour field's values at the ends of the map, and how values between map onto it; the
  // tubes carry scale coordinates (settings.colourRange is the range's), the bar shows values.
  render::ColourScale colourScale;
  render::ValueRange colourSeen;  // the finite values the tubes carry (positive ones for log)
  std::string colourLabel;
  std::string colourUnit;               // empty where the data give none
  std::vector<float> contextScalars;    // brick-ordered; empty without --volume
  render::ChannelValues colourChannel;  // the --colour-by channel, when it is one
  render::OrbitCamera camera;
};

// The unit of IntegrationTime: the input's length unit in `arc` mode (arc length), its time
// unit in `cell` and `time` modes; empty when the input does not say.
std::string integrationTimeUnit(flow::StepMode mode, const bricks::DatasetInfo& info);

// Sets the tube radius and what depends on it (the ambient-occlusion ray length).
void setTubeRadius(render::RenderSettings& settings, float radius);

// Throws InputError for a bad colour map, colour field, volume channel, range, camera, image size,
// number of ambient-occlusion rays, or a value that is not finite.
// `cells` give the context volume's channel and scalars to colour by; `volume` the domain.
RenderScene prepareScene(const RenderOptions& o, const Dataset& cells,
                         const flow::VectorVolume& volume, const flow::TraceSet& traces);

// Points scene.camera at what the options frame (--view-box, else the tubes or the domain, see
// RenderOptions::frame) from their direction, up axis, field of view and projection. Throws
// InputError for a bad one. The viewer calls it again to frame the traces as they are.
void frameCamera(RenderScene& scene, const RenderOptions& o, const flow::VectorVolume& volume);

// The box --axes follows, in physical coordinates: --view-box, else the domain.
std::pair<glm::dvec3, glm::dvec3> axesBounds(const RenderOptions& o,
                                             const flow::VectorVolume& volume);
// The input's length unit short enough for a label: "kpc", or "code units" of
// "code units (1 = 3.1e+24 cm)"; empty when unknown.
std::string shortLengthUnit(const bricks::DatasetInfo& info);

// Moves scene.camera, keeping its direction and projection, to frame the scene's tubes as they
// are (the domain when there are none) at this aspect: the viewer's "frame all".
void frameTubes(RenderScene& scene, const flow::VectorVolume& volume, float aspect);

// The tube segments and colour range for traces (also used as traces grow in the viewer).
void updateTubes(RenderScene& scene, const RenderOptions& o, const Dataset& cells,
                 const flow::VectorVolume& volume, const flow::TraceSet& traces);

// Extends the scene's tubes by the polylines `recent` (flow::ProgressiveTraces::recent): their
// segments join the traces' before the outline, and an automatic colour range grows to hold
// their values. Returns the added segments; nothing, and the scene as it was, when the segments
// already made would change colour (a symmetric-log scale whose width follows the range): then
// updateTubes must make them all again.
std::optional<std::vector<shared::TubeSegment>> appendTubes(RenderScene& scene,
                                                            const RenderOptions& o,
                                                            const Dataset& cells,
                                                            const flow::VectorVolume& volume,
                                                            const flow::TraceSet& recent);

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
