#include "vector_volume.hpp"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <sstream>

#include "cell_gradients.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"
#include "value_range.hpp"

namespace amrstream::flow {

namespace {

// Images of the bricks across the periodic faces: for every shift of -1, 0 or +1 periods along
// each periodic axis (not all zero), the shifted brick whose domain reaches into the domain box.
std::vector<shared::Brick> periodicImages(const std::vector<shared::Brick>& bricks,
                                          const bricks::CellBox& domain,
                                          const PeriodicAxes& periodic) {
  std::vector<glm::ivec3> shifts;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        const glm::ivec3 s(x, y, z);
        if (s == glm::ivec3(0)) continue;
        bool allowed = true;
        for (int a = 0; a < 3; ++a) allowed = allowed && (s[a] == 0 || periodic[a]);
        if (allowed) shifts.push_back(s);
      }
  const glm::ivec3 period = domain.upper - domain.lower;
  const glm::ivec3 lowerDoubled = 2 * domain.lower, upperDoubled = 2 * domain.upper;
  std::vector<shared::Brick> images;
  for (const shared::Brick& brick : bricks) {
    const bricks::CellBox d = bricks::brickDomainDoubled(brick);
    for (const glm::ivec3& s : shifts) {
      const glm::ivec3 offset = 2 * s * period;
      if (glm::all(glm::lessThan(d.lower + offset, upperDoubled)) &&
          glm::all(glm::greaterThan(d.upper + offset, lowerDoubled))) {
        shared::Brick image = brick;
        image.lower += s * period;
        images.push_back(image);
      }
    }
  }
  return images;
}

std::string channelList(const bricks::AmrField& field) {
  std::string names;
  for (const bricks::Channel& c : field.channels()) names += (names.empty() ? "" : ", ") + c.name;
  return names;
}

}  // namespace

VectorVolume buildCellLayout(const bricks::AmrField& field, const VolumeOptions& options,
                             VolumeBuildTimes* times) {
  Stopwatch clock;
  bricks::BrickSet brickSet = bricks::buildBricks(field, options.bricks);
  VectorVolume volume;
  volume.originalBrickCount = brickSet.bricks.size();
  if (std::find(options.periodic.begin(), options.periodic.end(), true) != options.periodic.end()) {
    const std::vector<shared::Brick> images =
        periodicImages(brickSet.bricks, field.bounds(), options.periodic);
    brickSet.bricks.insert(brickSet.bricks.end(), images.begin(), images.end());
  }
  if (times) times->bricks = clock.seconds();

  clock.restart();
  volume.regions = bricks::buildRegions(brickSet.bricks);
  if (times) times->regions = clock.seconds();

  volume.bricks = std::move(brickSet.bricks);
  volume.cellIds = std::move(brickSet.cellIds);
  volume.domain = field.bounds();
  volume.periodic = options.periodic;
  volume.transform = field.transform();
  return volume;
}

VectorVolume buildVectorVolume(const bricks::AmrField& field, const VectorChannels& vector,
                               const VolumeOptions& options, VolumeBuildTimes* times) {
  checkArithmeticRange(field, vector, options.pointData);
  VolumeBuildTimes local;
  VectorVolume volume = buildCellLayout(field, options, &local);

  Stopwatch clock;
  const bricks::Channel* channels[3];
  for (int c = 0; c < 3; ++c) channels[c] = &field.channel(vector.channels[c]);
  std::vector<const bricks::Channel*> pointData;
  for (const std::string& name : options.pointData) pointData.push_back(&field.channel(name));
  const std::size_t slots = volume.cellIds.size(), channelCount = pointData.size();
  volume.values.resize(slots);
  volume.channelValues.resize(slots * channelCount);
  tbb::parallel_for(std::size_t(0), slots, [&](std::size_t slot) {
    const std::uint32_t cell = volume.cellIds[slot];
    volume.values[slot] =
        glm::vec3(channels[0]->values[cell], channels[1]->values[cell], channels[2]->values[cell]);
    for (std::size_t c = 0; c < channelCount; ++c)
      volume.channelValues[slot * channelCount + c] = pointData[c]->values[cell];
  });
  local.gather = clock.seconds();

  volume.channelNames = options.pointData;
  volume.vectorName = vector.name;
  if (options.interpolant == Interpolant::Linear) {
    clock.restart();
    volume.interpolant = Interpolant::Linear;
    volume.vectorGradients = cellGradients(
        volume, std::span<const float>(&volume.values[0].x, 3 * volume.values.size()), 3);
    volume.channelGradients = cellGradients(volume, volume.channelValues, channelCount);
    local.gradients = clock.seconds();
  }
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

std::vector<std::string> choosePointData(const bricks::AmrField& field,
                                         const VectorChannels& vector, const std::string& request) {
  std::vector<std::string> names;
  if (request.empty() || request == "none") return names;
  if (request == "all") {
    for (const bricks::Channel& c : field.channels())
      if (std::find(vector.channels.begin(), vector.channels.end(), c.name) ==
          vector.channels.end())
        names.push_back(c.name);
    return names;
  }
  std::stringstream list(request);
  for (std::string name; std::getline(list, name, ',');) {
    if (name.empty()) continue;
    if (!field.findChannel(name))
      throw InputError("--point-data", fmt::format("no channel '{}' in {}; the channels are: {}",
                                                   name, field.source(), channelList(field)));
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

}  // namespace amrstream::flow
