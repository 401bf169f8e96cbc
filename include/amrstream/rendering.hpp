#pragma once
// Rendering traces as tubes: how they look (radius, colour field and map, ambient occlusion),
// the context volume, the camera, and an image rendered on a Vulkan device.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "amrstream/backend.hpp"
#include "amrstream/field.hpp"
#include "amrstream/log.hpp"
#include "amrstream/settings.hpp"
#include "amrstream/tracing.hpp"

namespace amrstream {

// Bounds of the options below: the image's sides in pixels, and the work per image, which is
// pixels x frames x (1 + ambient-occlusion rays): 4096 frames of 256 rays take hours on a fast
// GPU, and the image stops changing long before.
inline constexpr std::uint32_t kMinImageSide = std::uint32_t(settings::kWidth.least);
inline constexpr std::uint32_t kMaxImageSide = std::uint32_t(settings::kWidth.most);
inline constexpr std::uint32_t kMaxRenderFrames = std::uint32_t(settings::kFrames.most);
inline constexpr std::uint32_t kMaxAoSamples = std::uint32_t(settings::kAoSamples.most);

// How tubes look and the camera: the settings of amrstream/settings.hpp the comments name.
struct RenderOptions {
  std::uint32_t width = std::uint32_t(settings::kWidth.fallback);    // width
  std::uint32_t height = std::uint32_t(settings::kHeight.fallback);  // height
  std::vector<float> camera;  // camera: azimuth, elevation (degrees)[, zoom]
  std::string view;           // view: a named view; empty: the camera's, or 35, 25
  float zoom = float(settings::kZoom.fallback);         // zoom: > 1 closer; multiplies the camera's
  std::string up{settings::kUp.shown};                  // up: the axis up on screen
  float fovDegrees = float(settings::kFov.fallback);    // fov: vertical (an orthographic height)
  std::string projection{settings::kProjection.shown};  // projection
  std::string frame{settings::kFrame.shown};            // frame: "traces" or "domain"
  std::vector<double> lookAt;                // look_at: x,y,z; empty: the framed box's centre
  std::vector<double> viewBox;               // view_box: x0,y0,z0,x1,y1,z1; empty: see `frame`
  std::optional<float> tubeRadius;           // tube_radius: finest cells
  std::optional<double> tubeRadiusPhysical;  // tube_radius_physical: the input's length units
  float tubeRadiusOfView = float(settings::kTubeRadiusView.fallback);  // tube_radius_view
  float radiusByColour = float(settings::kRadiusByColour.fallback);    // radius_by_colour
  std::string colourBy{settings::kColourBy.shown};                     // colour_by
  // IntegrationTime's unit on the colour bar of colour_by time; empty: as the traces were
  // traced, where renderImage knows it.
  std::string timeUnit;
  std::string colourMap{settings::kColourMap.shown};      // colour_map
  std::string colourScale{settings::kColourScale.shown};  // colour_scale
  std::optional<double> symlogWidth;                      // symlog_width: default 1e-3 of the range
  std::vector<float> range;                               // range: min, max of the colour field
  std::string outline{settings::kOutline.shown};          // outline: "domain", "bricks" or "none"
  bool axes = false;                                      // axes
  bool triad = true;                                      // triad
  bool scaleBar = false;                                  // scale_bar
  std::string background;                                 // background; empty: a grey gradient
  std::uint32_t aoSamples = std::uint32_t(settings::kAoSamples.fallback);  // ao_samples
  std::string volume;                                                      // volume
  std::vector<float> volumeRange;                                          // volume_range
  float volumeOpacity = float(settings::kVolumeOpacity.fallback);          // volume_opacity
  bool linearVolume = false;                                               // linear_volume
  std::uint32_t frames = std::uint32_t(settings::kFrames.fallback);        // frames
  bool colourBar = true;                                                   // colour_bar
};

// An 8-bit RGBA image, row-major, top row first, sRGB, not premultiplied.
struct Image {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes
};

// An image of traces: `frames` jittered samples per pixel accumulated, with the colour bar.
struct RenderedImage {
  Image image;
  std::string backend, device;
  std::size_t segments = 0;
  double setupSeconds = 0.0, renderSeconds = 0.0, kernelSecondsPerFrame = 0.0;
};

// The colour maps' names, e.g. "viridis, magma, ...".
std::string colourMapNames();

// Throws InputError when the request names the CPU backend: rendering needs a Vulkan device.
// (renderImage checks it too; callers that trace first check it before tracing.)
void requireRenderBackend(const BackendRequest& request);

// The traces' tubes in the field, whose dataset gives the context volume and the channels tubes
// may be coloured by (the field must keep it). IntegrationTime's unit on a colour bar of
// colourBy "time" is options.timeUnit, else the traces' step mode's where they were traced here.
// Progress: stage "rendering", frames. Throws InputError for the CPU backend, bad options and
// options.frames outside 1..kMaxRenderFrames, vk::ContextError when the device lacks what the
// backend needs.
RenderedImage renderImage(const BackendRequest& request, const RenderOptions& options,
                          const Field& field, const Traces& traces, const Reporter& reporter = {});

// Writes the image as a PNG (through a temporary file).
void writePng(const std::filesystem::path& path, const Image& image);

// Says how many lines and points `traces` (read from `path`) hold, and throws InputError naming
// the file when none of their points lies in the field's domain (traced in another dataset?).
void checkTracesInDomain(const std::string& path, const Traces& traces, const Field& field,
                         const Log& log = {});

}  // namespace amrstream
