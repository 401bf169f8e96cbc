#include "line_samples.hpp"

#include <tbb/parallel_for.h>

#include <limits>

#include "flow/sampler.hpp"

namespace amrstream::slice {

LineSamples sampleAlongLines(const flow::VectorVolume& volume, const SlicePlane& plane,
                             const std::vector<PlaneLine>& lines) {
  LineSamples samples;
  for (const PlaneLine& line : lines)
    for (const glm::dvec2& p : line.points) samples.positions.push_back(plane.physical(p));
  for (const PlaneLine& line : lines)
    samples.offsets.push_back(samples.offsets.back() + line.points.size());
  const std::size_t points = samples.positions.size(), channelCount = volume.channelCount();
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  samples.vectors.assign(points, glm::vec3(kNaN));
  samples.channels.assign(points * channelCount, kNaN);
  tbb::parallel_for(std::size_t(0), lines.size(), [&](std::size_t line) {
    flow::RegionCache cache;
    std::vector<float> values(channelCount);
    for (std::uint64_t n = samples.offsets[line]; n < samples.offsets[line + 1]; ++n) {
      const flow::CellPoint p = flow::wrapPeriodic(
          volume, flow::toCellPoint(volume.transform.toCellUnits(samples.positions[n])));
      const flow::VectorSample sample = flow::sampleVector(volume, p, &cache);
      if (!sample.valid) continue;
      samples.vectors[n] = sample.value;
      if (channelCount == 0) continue;
      flow::sampleChannels(volume, sample.region, p, values);
      std::copy(values.begin(), values.end(), samples.channels.begin() + n * channelCount);
    }
  });
  return samples;
}

std::vector<std::vector<float>> valuesAlongLines(const LineSamples& samples,
                                                 std::size_t channelCount, int channel) {
  std::vector<std::vector<float>> values(samples.offsets.size() - 1);
  for (std::size_t line = 0; line < values.size(); ++line)
    for (std::uint64_t n = samples.offsets[line]; n < samples.offsets[line + 1]; ++n)
      values[line].push_back(channel < 0
                                 ? glm::length(samples.vectors[n])
                                 : samples.channels[n * channelCount + std::size_t(channel)]);
  return values;
}

}  // namespace amrstream::slice
