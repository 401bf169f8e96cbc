#pragma once
// The renderer's input made from traces (tube segments, settings, colour map and camera) and the
// steps that make and update it: what renderImage and the viewer share.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "amrstream/rendering.hpp"
#include "bricks/amr_field.hpp"
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

// The renderer's input made from traces: tube segments, settings, colour map and camera.
struct RenderScene {
  // The traces' tubes, then the outline's (RenderOptions::outline), which updateTubes keeps.
  std::vector<shared::TubeSegment> segments;
  std::vector<shared::TubeSegment> outline;
  // The box around the traces' segments (not the outline's), scene units; none without segments.
  std::optional<std::pair<glm::vec3, glm::vec3>> tracesBox;
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
std::string integrationTimeUnit(flow::StepMode mode, const DatasetInfo& info);

// Sets the tube radius and what depends on it (the ambient-occlusion ray length).
void setTubeRadius(render::RenderSettings& settings, float radius);

// Throws InputError for a bad colour map, colour field, volume channel, range, camera, image size,
// number of ambient-occlusion rays, or a value that is not finite.
// `cells` give the context volume's channel and scalars to colour by; `volume` the domain.
// `info` (the field's) gives the units of what the tubes are coloured by.
RenderScene prepareScene(const RenderOptions& o, const bricks::AmrField& cells,
                         const flow::VectorVolume& volume, const flow::TraceSet& traces,
                         const DatasetInfo& info);

// Points scene.camera at what the options frame (--view-box, else the tubes or the domain, see
// RenderOptions::frame) from their direction (side on to the traces where they give none:
// render/side_on_view.hpp), up axis, field of view and projection. Throws
// InputError for a bad one. The viewer calls it again to frame the traces as they are.
void frameCamera(RenderScene& scene, const RenderOptions& o, const flow::VectorVolume& volume);

// The box --axes follows, in physical coordinates: --view-box, else what the camera frames (the
// box around the scene's traces, or the domain).
std::pair<glm::dvec3, glm::dvec3> axesBounds(const RenderOptions& o, const RenderScene& scene,
                                             const flow::VectorVolume& volume);
// The input's length unit short enough for a label: "kpc", or "code units" of
// "code units (1 = 3.1e+24 cm)"; empty when unknown.
std::string shortLengthUnit(const DatasetInfo& info);

// Moves scene.camera, keeping its direction and projection, to frame the scene's tubes as they
// are (the domain when there are none) at this aspect: the viewer's "frame all".
void frameTubes(RenderScene& scene, const flow::VectorVolume& volume, float aspect);

// The colour bar's label and unit for options.colourBy: "|vector|" for speed, "age" for the
// times of streaklines, else the name; the unit where known.
void titleColourBar(RenderScene& scene, const RenderOptions& o, const flow::TraceSet& traces,
                    const DatasetInfo& info);

// The finite values a scale of `kind` can show (positive ones for log) among `values`, added to
// `seen` (start from nothingSeen()).
render::ValueRange widenSeen(render::ValueRange seen, render::ScaleKind kind,
                             std::span<const float> values);
render::ValueRange nothingSeen();

// A colour scale of `kind` over `range` where given, else over the values seen (a range around
// a lone value; 0..0 or 1..1 widened when none were seen), with symlog's linear width given or
// its default. Throws InputError naming range (or colour_scale) for a scale checkScale refuses.
render::ColourScale colourScaleOver(render::ScaleKind kind,
                                    const std::optional<render::ValueRange>& range,
                                    render::ValueRange seen, std::optional<double> symlogWidth);

// The library's Image of a raster.
Image publicImage(render::Image image);

// The scene's colour range (the tubes' scale coordinates) over its whole colour scale.
void setColourRange(RenderScene& scene);

// The tube segments and colour range for traces (also used as traces grow in the viewer).
void updateTubes(RenderScene& scene, const RenderOptions& o, const bricks::AmrField& cells,
                 const flow::VectorVolume& volume, const flow::TraceSet& traces);

// Extends the scene's tubes by the polylines `recent` (flow::ProgressiveTraces::recent): their
// segments join the traces' before the outline, and an automatic colour range grows to hold
// their values. Returns the added segments; nothing, and the scene as it was, when the segments
// already made would change colour (a symmetric-log scale whose width follows the range): then
// updateTubes must make them all again.
std::optional<std::vector<shared::TubeSegment>> appendTubes(RenderScene& scene,
                                                            const RenderOptions& o,
                                                            const bricks::AmrField& cells,
                                                            const flow::VectorVolume& volume,
                                                            const flow::TraceSet& recent);

}  // namespace amrstream
