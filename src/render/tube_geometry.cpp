#include "tube_geometry.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

#include "flow/sampler.hpp"
#include "util/input_error.hpp"

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
    colour.values = traces.times;
    return colour;
  }
  if (!field.findChannel(name)) {
    std::string choices = "speed, time";
    for (const bricks::Channel& c : field.channels()) choices += ", " + c.name;
    throw InputError("--colour-by", fmt::format("no field '{}'; choose one of: {}", name, choices));
  }
  if (channel.name != name) channel = {name, flow::gatherScalar(field, volume, name)};
  const std::vector<float>& scalars = channel.values;
  tbb::parallel_for(std::uint32_t(0), traces.seedCount, [&](std::uint32_t seed) {
    flow::RegionCache cache;
    for (std::uint32_t p = 0; p < traces.pointCounts[seed]; ++p) {
      const std::size_t i = traces.at(seed, p);
      const glm::vec3 cell(volume.transform.toCellUnits(glm::dvec3(traces.positions[i])));
      colour.values[i] = flow::sampleScalar(volume, scalars, cell, &cache)
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
                                                   const bricks::WorldTransform& transform) {
  std::vector<shared::TubeSegment> segments;
  const auto cell = [&](std::size_t i) {
    return glm::vec3(transform.toCellUnits(glm::dvec3(traces.positions[i])));
  };
  for (std::uint32_t seed = 0; seed < traces.seedCount; ++seed) {
    const std::uint32_t n = traces.pointCounts[seed];
    if (n == 1) {
      const std::size_t i = traces.at(seed, 0);
      segments.push_back({cell(i), colour.values[i], cell(i), colour.values[i]});
    }
    for (std::uint32_t p = 0; p + 1 < n; ++p) {
      const std::size_t i = traces.at(seed, p), j = traces.at(seed, p + 1);
      segments.push_back({cell(i), colour.values[i], cell(j), colour.values[j]});
    }
  }
  return segments;
}

}  // namespace amrstream::render
