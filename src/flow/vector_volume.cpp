#include "vector_volume.hpp"

#include <tbb/parallel_for.h>

#include "util/stopwatch.hpp"

namespace amrstream::flow {

VectorVolume buildVectorVolume(const bricks::AmrField& field, const VectorChannels& vector,
                               const bricks::BrickBuildOptions& options, VolumeBuildTimes* times) {
  VolumeBuildTimes local;
  Stopwatch clock;
  bricks::BrickSet brickSet = bricks::buildBricks(field, options);
  local.bricks = clock.seconds();

  clock.restart();
  VectorVolume volume;
  volume.regions = bricks::buildRegions(brickSet.bricks);
  local.regions = clock.seconds();

  clock.restart();
  const bricks::Channel* channels[3];
  for (int c = 0; c < 3; ++c) channels[c] = &field.channel(vector.channels[c]);
  volume.values.resize(brickSet.cellIds.size());
  tbb::parallel_for(std::size_t(0), brickSet.cellIds.size(), [&](std::size_t slot) {
    const std::uint32_t cell = brickSet.cellIds[slot];
    volume.values[slot] =
        glm::vec3(channels[0]->values[cell], channels[1]->values[cell], channels[2]->values[cell]);
  });
  local.gather = clock.seconds();

  volume.bricks = std::move(brickSet.bricks);
  volume.cellIds = std::move(brickSet.cellIds);
  volume.domain = field.bounds();
  volume.transform = field.transform();
  volume.vectorName = vector.name;
  if (times) *times = local;
  return volume;
}

std::vector<float> gatherScalar(const bricks::AmrField& field, const VectorVolume& volume,
                                std::string_view channel) {
  const bricks::Channel& source = field.channel(channel);
  std::vector<float> values(volume.cellIds.size());
  tbb::parallel_for(std::size_t(0), values.size(),
                    [&](std::size_t slot) { values[slot] = source.values[volume.cellIds[slot]]; });
  return values;
}

}  // namespace amrstream::flow
