#include "uniform_resample.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <span>

#include "amrstream/error.hpp"
#include "sampler.hpp"
#include "util/host_memory.hpp"

namespace amrstream::flow {

void checkGridCounts(std::span<const std::uint64_t> dims) {
  if (dims.size() != 1 && dims.size() != 3)
    throw settingError("dims", "give one count (the longest axis) or three (NX,NY,NZ)");
  for (const std::uint64_t n : dims)
    if (n < 1 || n > 65535) throw settingError("dims", fmt::format("{} is outside 1..65535", n));
}

UniformGridSpec uniformGridSpec(const VectorVolume& volume, std::span<const std::uint64_t> dims,
                                std::span<const double> box) {
  checkGridCounts(dims);
  UniformGridSpec spec;
  spec.lower = volume.transform.toPhysical(glm::dvec3(volume.domain.lower));
  spec.upper = volume.transform.toPhysical(glm::dvec3(volume.domain.upper));
  if (!box.empty()) {
    if (box.size() != 6) throw settingError("box", "give x0,y0,z0,x1,y1,z1");
    spec.lower = {box[0], box[1], box[2]};
    spec.upper = {box[3], box[4], box[5]};
    if (!glm::all(glm::lessThan(spec.lower, spec.upper)) ||
        !std::all_of(box.begin(), box.end(), [](double v) { return std::isfinite(v); }))
      throw settingError("box", "each upper bound must be above its lower bound");
  }
  if (dims.size() == 3) {
    spec.dims = {std::uint32_t(dims[0]), std::uint32_t(dims[1]), std::uint32_t(dims[2])};
  } else {
    const glm::dvec3 extent = spec.upper - spec.lower;
    const double longest = std::max({extent.x, extent.y, extent.z});
    for (int a = 0; a < 3; ++a)
      spec.dims[a] = std::max<std::uint32_t>(
          1, std::uint32_t(std::lround(double(dims[0]) * extent[a] / longest)));
  }
  const double bytes = double(spec.pointCount()) * double(12 + 4 * volume.channelCount() + 1);
  const double limit = kTraceMemoryShare * physicalMemoryBytes();
  if (limit > 0.0 && bytes > limit)
    throw settingError("dims", fmt::format("{} x {} x {} points need {:.1f} GiB, more than the "
                                           "{:.1f} GiB (3/4 of the memory) this machine allows",
                                           spec.dims[0], spec.dims[1], spec.dims[2], bytes / 0x1p30,
                                           limit / 0x1p30));
  return spec;
}

GridSamples sampleRows(const VectorVolume& volume, std::size_t rowLength, std::size_t rows,
                       const std::function<CellPoint(std::size_t, std::size_t)>& pointAt,
                       const std::function<void(std::size_t)>& progress) {
  GridSamples samples;
  const std::size_t points = rowLength * rows, channelCount = volume.channelCount();
  samples.vectors.assign(points, glm::vec3(0.0f));
  samples.channels.assign(points * channelCount, 0.0f);
  samples.valid.assign(points, 0);
  std::atomic<std::uint64_t> validCount{0};
  std::size_t rowsDone = 0;
  std::mutex progressMutex;
  tbb::parallel_for(std::size_t(0), rows, [&](std::size_t row) {
    RegionCache cache;
    std::vector<float> values(channelCount);
    std::uint64_t rowValid = 0;
    for (std::size_t i = 0; i < rowLength; ++i) {
      const CellPoint p = pointAt(i, row);
      const VectorSample sample = sampleVector(volume, p, &cache);
      if (!sample.valid) continue;
      const std::size_t n = i + rowLength * row;
      samples.vectors[n] = sample.value;
      samples.valid[n] = 1;
      ++rowValid;
      if (channelCount == 0) continue;
      sampleChannels(volume, sample.region, p, values);
      std::copy(values.begin(), values.end(), samples.channels.begin() + n * channelCount);
    }
    validCount += rowValid;
    if (progress) {
      const std::lock_guard lock(progressMutex);
      progress(++rowsDone);
    }
  });
  samples.validCount = validCount;
  return samples;
}

GridSamples sampleGrid(const VectorVolume& volume, const AffineGrid& grid,
                       const std::function<void(std::size_t)>& progress) {
  const std::size_t ny = grid.dims[1];
  return sampleRows(
      volume, grid.dims[0], ny * grid.dims[2],
      [&](std::size_t i, std::size_t row) {
        const std::size_t j = row % ny, k = row / ny;
        const glm::dvec3 physical = grid.origin + grid.steps[1] * double(j) +
                                    grid.steps[2] * double(k) + grid.steps[0] * double(i);
        return wrapPeriodic(volume, toCellPoint(volume.transform.toCellUnits(physical)));
      },
      progress);
}

UniformGrid resampleUniform(const VectorVolume& volume, const UniformGridSpec& spec,
                            const std::function<void(std::size_t)>& progress) {
  const glm::dvec3 spacing = spec.spacing();
  AffineGrid grid;
  grid.origin = spec.origin();
  grid.steps = {glm::dvec3(spacing.x, 0, 0), glm::dvec3(0, spacing.y, 0),
                glm::dvec3(0, 0, spacing.z)};
  grid.dims = spec.dims;
  UniformGrid uniform;
  static_cast<GridSamples&>(uniform) = sampleGrid(volume, grid, progress);
  uniform.spec = spec;
  return uniform;
}

}  // namespace amrstream::flow
