#include "tube_geometry.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "amrstream/closest_name.hpp"
#include "amrstream/error.hpp"
#include "flow/cell_gradients.hpp"
#include "flow/sampler.hpp"

namespace amrstream::render {

ColourField colourFieldOf(const flow::TraceSet& traces, const std::string& name,
                          const bricks::AmrField& field, const flow::VectorVolume& volume,
                          ChannelValues& channel) {
  ColourField colour{name, std::vector<float>(traces.positions.size(), 0.0f)};
  if (name == "speed") {
    for (std::size_t i = 0; i < colour.values.size(); ++i)
      colour.values[i] = glm::length(traces.vectors[i]);
    return colour;
  }
  if (name == "time") {
    colour.values.assign(traces.times.begin(), traces.times.end());
    return colour;
  }
  if (!field.findChannel(name)) {
    std::string choices = "speed, time";
    std::vector<std::string> candidates = {"speed", "time"};
    for (const Channel& c : field.channels()) {
      choices += ", " + c.name;
      candidates.push_back(c.name);
    }
    throw settingError("colour_by", fmt::format("no field '{}'{}; choose one of: {}", name,
                                                didYouMean(name, candidates), choices));
  }
  const auto traced = std::find(traces.channelNames.begin(), traces.channelNames.end(), name);
  if (traced != traces.channelNames.end()) {
    const std::size_t c = std::size_t(traced - traces.channelNames.begin());
    for (std::size_t i = 0; i < colour.values.size(); ++i)
      colour.values[i] = traces.channels[i * traces.channelCount() + c];
    return colour;
  }
  if (channel.name != name) {
    channel = {name, flow::gatherScalar(field, volume, name), {}};
    if (volume.interpolant == flow::Interpolant::Linear)
      channel.gradients = flow::cellGradients(volume, channel.values, 1);
  }
  const std::vector<float>& scalars = channel.values;
  tbb::parallel_for(std::size_t(0), traces.lineCount(), [&](std::size_t line) {
    flow::RegionCache cache;
    for (std::uint64_t i = traces.offsets[line]; i < traces.offsets[line + 1]; ++i) {
      const flow::CellPoint cell =
          flow::toCellPoint(volume.transform.toCellUnits(glm::dvec3(traces.positions[i])));
      colour.values[i] = flow::sampleScalar(volume, scalars, cell, &cache, channel.gradients)
                             .value_or(std::numeric_limits<float>::quiet_NaN());
    }
  });
  return colour;
}

ValueRange rangeOf(std::span<const float> values) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (const float v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (lo > hi) return {};
  return {lo, hi};
}

std::vector<shared::TubeSegment> buildTubeSegments(const flow::TraceSet& traces,
                                                   const ColourField& colour,
                                                   const WorldTransform& transform) {
  std::vector<shared::TubeSegment> segments;
  const auto cell = [&](std::uint64_t i) {
    return glm::vec3(transform.toCellUnits(glm::dvec3(traces.positions[i])));
  };
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    const std::uint64_t first = traces.offsets[line], end = traces.offsets[line + 1];
    if (end - first == 1)
      segments.push_back({cell(first), colour.values[first], cell(first), colour.values[first]});
    for (std::uint64_t i = first; i + 1 < end; ++i) {
      // A line that crosses a periodic face goes on from the other side: no tube across the box.
      if (traces.periodic.wraps(traces.positions[i], traces.positions[i + 1])) continue;
      segments.push_back({cell(i), colour.values[i], cell(i + 1), colour.values[i + 1]});
    }
  }
  return segments;
}

std::vector<shared::TubeSegment> boxOutline(glm::vec3 lower, glm::vec3 upper) {
  const float outline = AMRSTREAM_OUTLINE_VALUE;
  const auto corner = [&](int bits) {
    return glm::vec3((bits & 1) ? upper.x : lower.x, (bits & 2) ? upper.y : lower.y,
                     (bits & 4) ? upper.z : lower.z);
  };
  std::vector<shared::TubeSegment> edges;
  for (int bits = 0; bits < 8; ++bits)
    for (int axis = 0; axis < 3; ++axis)
      if ((bits & (1 << axis)) == 0)
        edges.push_back({corner(bits), outline, corner(bits | (1 << axis)), outline});
  return edges;
}

float segmentRadius(const shared::TubeSegment& segment, float radius, float leastFraction,
                    const ValueRange& range) {
  if (std::min(segment.valueA, segment.valueB) < 0.1f * AMRSTREAM_OUTLINE_VALUE)
    return shared::kOutlineRadiusFraction * radius;
  const float span = range.max - range.min;
  const float mean = 0.5f * segment.valueA + 0.5f * segment.valueB;
  const float t = span > 0.0f ? std::clamp((mean - range.min) / span, 0.0f, 1.0f) : 1.0f;
  return radius * (leastFraction + (1.0f - leastFraction) * t);
}

}  // namespace amrstream::render
