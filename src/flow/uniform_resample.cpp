#include "uniform_resample.hpp"

#include <tbb/parallel_for.h>

#include <atomic>
#include <mutex>
#include <span>

#include "sampler.hpp"

namespace amrstream::flow {

UniformGrid resampleUniform(const VectorVolume& volume, const UniformGridSpec& spec,
                            const std::function<void(std::size_t)>& progress) {
  UniformGrid grid;
  grid.spec = spec;
  const std::size_t points = spec.pointCount(), channelCount = volume.channelCount();
  grid.vectors.assign(points, glm::vec3(0.0f));
  grid.channels.assign(points * channelCount, 0.0f);
  grid.valid.assign(points, 0);
  const glm::dvec3 origin = spec.origin(), spacing = spec.spacing();
  const std::size_t nx = spec.dims[0], ny = spec.dims[1], nz = spec.dims[2];
  std::atomic<std::uint64_t> validCount{0};
  std::size_t rowsDone = 0;
  std::mutex progressMutex;
  tbb::parallel_for(std::size_t(0), nz * ny, [&](std::size_t row) {
    const std::size_t j = row % ny, k = row / ny;
    RegionCache cache;
    std::vector<float> values(channelCount);
    std::uint64_t rowValid = 0;
    for (std::size_t i = 0; i < nx; ++i) {
      const glm::dvec3 physical = origin + spacing * glm::dvec3(double(i), double(j), double(k));
      const CellPoint p =
          wrapPeriodic(volume, toCellPoint(volume.transform.toCellUnits(physical)));
      const VectorSample sample = sampleVector(volume, p, &cache);
      if (!sample.valid) continue;
      const std::size_t n = i + nx * row;
      grid.vectors[n] = sample.value;
      grid.valid[n] = 1;
      ++rowValid;
      if (channelCount == 0) continue;
      sampleChannels(volume, sample.region, p, values);
      std::copy(values.begin(), values.end(), grid.channels.begin() + n * channelCount);
    }
    validCount += rowValid;
    if (progress) {
      const std::lock_guard lock(progressMutex);
      progress(++rowsDone);
    }
  });
  grid.validCount = validCount;
  return grid;
}

}  // namespace amrstream::flow
