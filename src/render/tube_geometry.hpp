#pragma once
// Tubes from traces: one capsule per pair of consecutive trace points, in finest-cell units, with
// the colour field's value at both ends, and the range of those values for the colour map.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "../../shaders/glsl/shared/render_types.h"
#include "bricks/amr_field.hpp"
#include "flow/trace_set.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream::render {

// What colours the tubes: "speed" (the traced vector's length), "time" (IntegrationTime), or
// the name of a scalar channel: the traces' point data when they carry it, else sampled from the
// input at every trace point.
struct ColourField {
  std::string name = "speed";
  std::vector<float> values;  // one per trace point, indexed like TraceSet::positions
};

// A scalar channel in brick order (flow::gatherScalar), kept between calls of colourFieldOf so
// that traces growing frame by frame do not gather it again.
struct ChannelValues {
  std::string name;
  std::vector<float> values;
  std::vector<glm::vec3> gradients;  // the linear interpolant's (flow::cellGradients); else empty
};

// Throws InputError listing the choices when `name` is neither speed, time nor a channel of
// `field`. A channel is gathered into `channel` unless it already holds it.
ColourField colourFieldOf(const flow::TraceSet& traces, const std::string& name,
                          const bricks::AmrField& field, const flow::VectorVolume& volume,
                          ChannelValues& channel);

struct ValueRange {
  float min = 0.0f;
  float max = 1.0f;

  bool operator==(const ValueRange&) const = default;
};

// The range of the finite values (0..1 when there are none).
ValueRange rangeOf(std::span<const float> values);

// A line of one point becomes a sphere (a == b); lines of no points are skipped, and so are the
// steps where a periodic line wraps.
std::vector<shared::TubeSegment> buildTubeSegments(const flow::TraceSet& traces,
                                                   const ColourField& colour,
                                                   const WorldTransform& transform);

// A segment's radius when radii follow the colour field (capsule.glsl's segmentRadius):
// `leastFraction` of `radius` at range.min, all of it at range.max, in proportion to the mean of
// the segment's two values between; outline segments are shared::kOutlineRadiusFraction of it.
float segmentRadius(const shared::TubeSegment& segment, float radius, float leastFraction,
                    const ValueRange& range);

// The twelve edges of a box (scene units) as outline segments (AMRSTREAM_OUTLINE_VALUE).
std::vector<shared::TubeSegment> boxOutline(glm::vec3 lower, glm::vec3 upper);

}  // namespace amrstream::render
