#include "vector_volume.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>

#include "amrstream/closest_name.hpp"
#include "amrstream/error.hpp"
#include "cell_gradients.hpp"
#include "frame_velocity.hpp"
#include "gradient_vector.hpp"
#include "util/stopwatch.hpp"
#include "value_range.hpp"

namespace amrstream::flow {

std::vector<glm::ivec3> periodicShifts(const PeriodicAxes& periodic) {
  std::vector<glm::ivec3> shifts{glm::ivec3(0)};
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x) {
        const glm::ivec3 s(x, y, z);
        if (s == glm::ivec3(0)) continue;
        bool allowed = true;
        for (int a = 0; a < 3; ++a) allowed = allowed && (s[a] == 0 || periodic[a]);
        if (allowed) shifts.push_back(s);
      }
  return shifts;
}

namespace {

// Images of the bricks across the periodic faces: for every non-zero periodic shift, the shifted
// brick whose domain reaches into the domain box.
std::vector<shared::Brick> periodicImages(const std::vector<shared::Brick>& bricks,
                                          const CellBox& domain, const PeriodicAxes& periodic) {
  std::vector<glm::ivec3> shifts = periodicShifts(periodic);
  shifts.erase(shifts.begin());
  const glm::i64vec3 period(domain.upper - domain.lower);
  const glm::i64vec3 lowerDoubled = std::int64_t(2) * glm::i64vec3(domain.lower),
                     upperDoubled = std::int64_t(2) * glm::i64vec3(domain.upper);
  std::vector<shared::Brick> images;
  for (const shared::Brick& brick : bricks) {
    const CellBox d = bricks::brickDomainDoubled(brick);
    for (const glm::ivec3& s : shifts) {
      const glm::i64vec3 offset = std::int64_t(2) * glm::i64vec3(s) * period;
      if (glm::all(glm::lessThan(glm::i64vec3(d.lower) + offset, upperDoubled)) &&
          glm::all(glm::greaterThan(glm::i64vec3(d.upper) + offset, lowerDoubled))) {
        shared::Brick image = brick;
        image.lower += s * glm::ivec3(period);
        images.push_back(image);
      }
    }
  }
  return images;
}

// Cell coordinates as the field has them when they lie within 2^20 of the origin; otherwise moved
// so that the domain is centred on it, where the region lattice (doubled coordinates) fits 32
// bits at any depth and float positions in cell units keep the most precision. The transform
// moves by the same whole cells, so physical positions are unchanged.
struct CentredCells {
  CellBox domain;
  WorldTransform transform;
};

CentredCells centreCells(const bricks::AmrField& field, std::vector<shared::Brick>& bricks) {
  const CellBox bounds = field.bounds();
  constexpr int kNear = 1 << 20;
  if (glm::all(glm::greaterThanEqual(bounds.lower, glm::ivec3(-kNear))) &&
      glm::all(glm::lessThanEqual(bounds.upper, glm::ivec3(kNear))))
    return {bounds, field.transform()};
  const glm::ivec3 centre = bounds.lower + (bounds.upper - bounds.lower) / 2;
  for (shared::Brick& brick : bricks) brick.lower -= centre;
  WorldTransform transform = field.transform();
  transform.origin += transform.spacing * glm::dvec3(centre);
  return {{bounds.lower - centre, bounds.upper - centre}, transform};
}

}  // namespace

namespace {

// Crops every brick to the cells whose tents reach into `box` (one cell more on each side) or,
// along periodic axes, into its translates by a period (samples there wrap to the other side);
// drops bricks left with none. The kept cells keep their order and the bricks theirs.
//
// A sample at p sums weights from p - lower, lower a brick's corner. That difference is exact in
// float when lower >= 0 (cells are aligned to their width, so a cell whose tent reaches p has
// |p - lower| <= p), and then cropping, which moves lower, changes nothing. Where lower < 0, on a
// brick or on its image a period below, p - lower rounds, and differently for another lower:
// such bricks keep their lower corner along that axis.
void keepAround(bricks::BrickSet& set, const VolumeOptions::Box& box, const CellBox& domain,
                const PeriodicAxes& periodic) {
  std::vector<VolumeOptions::Box> boxes;
  const glm::dvec3 period(domain.upper - domain.lower);
  for (const glm::ivec3& s : periodicShifts(periodic))
    boxes.push_back({box.lower + glm::dvec3(s) * period, box.upper + glm::dvec3(s) * period});
  std::vector<shared::Brick> bricks;
  std::vector<std::uint32_t> cellIds;
  for (const shared::Brick& brick : set.bricks) {
    const double width = std::ldexp(1.0, brick.level);
    const glm::dvec3 lower(brick.lower);
    glm::ivec3 lo = brick.size, hi(0);
    for (const VolumeOptions::Box& b : boxes) {
      const glm::ivec3 l =
          glm::max(glm::ivec3(glm::floor((b.lower - lower) / width - 1.5)), glm::ivec3(0));
      const glm::ivec3 h =
          glm::min(glm::ivec3(glm::ceil((b.upper - lower) / width + 0.5)) + 1, brick.size);
      if (glm::any(glm::greaterThanEqual(l, h))) continue;
      lo = glm::min(lo, l);
      hi = glm::max(hi, h);
    }
    if (glm::any(glm::greaterThanEqual(lo, hi))) continue;
    const CellBox d = bricks::brickDomainDoubled(brick);
    for (int a = 0; a < 3; ++a) {
      const bool imageBelow = periodic[a] && d.upper[a] > 2 * domain.upper[a];
      if (brick.lower[a] < 0 || imageBelow) lo[a] = 0;
    }
    shared::Brick kept = brick;
    kept.lower = brick.lower + lo * (1 << brick.level);
    kept.size = hi - lo;
    kept.valueOffset = std::uint32_t(cellIds.size());
    for (int z = lo.z; z < hi.z; ++z)
      for (int y = lo.y; y < hi.y; ++y) {
        const std::size_t row =
            brick.valueOffset + std::size_t(brick.size.x) * (y + std::size_t(brick.size.y) * z);
        cellIds.insert(cellIds.end(), set.cellIds.begin() + std::ptrdiff_t(row + lo.x),
                       set.cellIds.begin() + std::ptrdiff_t(row + hi.x));
      }
    bricks.push_back(kept);
  }
  set.bricks = std::move(bricks);
  set.cellIds = std::move(cellIds);
}

}  // namespace

namespace {

// Whether `bricks` (disjoint dense boxes of cells) fill `domain`: their volumes, summed exactly
// (up to 2^90 finest cells each), equal the box's.
bool fillsDomain(std::span<const shared::Brick> bricks, const CellBox& domain) {
  using Volume = unsigned __int128;
  Volume filled = 0;
  for (const shared::Brick& b : bricks)
    filled += (Volume(b.size.x) * Volume(b.size.y) * Volume(b.size.z)) << (3 * b.level);
  const glm::ivec3 extent = domain.upper - domain.lower;
  return filled == Volume(extent.x) * Volume(extent.y) * Volume(extent.z);
}

// A layout from its bricks (centred, kept): their periodic images, the regions.
VectorVolume finishLayout(bricks::BrickSet brickSet, const CentredCells& centred,
                          const VolumeOptions& options, Stopwatch& clock, VolumeBuildTimes* times) {
  VectorVolume volume;
  volume.originalBrickCount = brickSet.bricks.size();
  volume.cellsFillDomain = fillsDomain(brickSet.bricks, centred.domain);
  if (std::find(options.periodic.begin(), options.periodic.end(), true) != options.periodic.end()) {
    const std::vector<shared::Brick> images =
        periodicImages(brickSet.bricks, centred.domain, options.periodic);
    brickSet.bricks.insert(brickSet.bricks.end(), images.begin(), images.end());
  }
  if (times) times->bricks = clock.seconds();

  clock.restart();
  volume.regions = bricks::buildRegions(brickSet.bricks, centred.domain);
  if (times) times->regions = clock.seconds();

  volume.bricks = std::move(brickSet.bricks);
  volume.cellIds = std::move(brickSet.cellIds);
  volume.domain = centred.domain;
  volume.periodic = options.periodic;
  volume.transform = centred.transform;
  return volume;
}

}  // namespace

VectorVolume buildCellLayout(const bricks::AmrField& field, const VolumeOptions& options,
                             VolumeBuildTimes* times) {
  Stopwatch clock;
  bricks::BrickSet brickSet = bricks::buildBricks(field, options.bricks);
  const CentredCells centred = centreCells(field, brickSet.bricks);
  if (options.keepAround)
    keepAround(brickSet, *options.keepAround, centred.domain, options.periodic);
  VectorVolume volume = finishLayout(std::move(brickSet), centred, options, clock, times);
  volume.planar = field.info().dimensions == 2;
  return volume;
}

VectorVolume cropCellLayout(const VectorVolume& whole, const VolumeOptions& options,
                            VolumeBuildTimes* times) {
  Stopwatch clock;
  bricks::BrickSet brickSet;
  brickSet.bricks.assign(whole.bricks.begin(),
                         whole.bricks.begin() + std::ptrdiff_t(whole.originalBrickCount));
  brickSet.cellIds = whole.cellIds;
  if (options.keepAround) keepAround(brickSet, *options.keepAround, whole.domain, options.periodic);
  VectorVolume volume =
      finishLayout(std::move(brickSet), {whole.domain, whole.transform}, options, clock, times);
  volume.planar = whole.planar;
  return volume;
}

VectorVolume buildVectorVolume(const bricks::AmrField& field, const VectorChannels& vector,
                               const VolumeOptions& options, VolumeBuildTimes* times) {
  for (const std::string& name : vector.sourceChannels()) field.channel(name);  // throw first
  for (const std::string& name : options.pointData) field.channel(name);
  VolumeBuildTimes local;
  VectorVolume volume = buildCellLayout(field, options, &local);
  fillVolumeValues(volume, field, vector, options, &local);
  if (times) *times = local;
  return volume;
}

void fillVolumeValues(VectorVolume& volume, const bricks::AmrField& field,
                      const VectorChannels& vector, const VolumeOptions& options,
                      VolumeBuildTimes* times) {
  for (const std::string& name : vector.sourceChannels()) field.channel(name);  // throw first
  for (const std::string& name : options.pointData) field.channel(name);
  const ChannelSource fromField = [&field](const std::string& name, const ChannelUse& use) {
    use(field.channel(name).values);
  };
  fillVolumeValues(volume, vector, options, field.source(), fromField, times);
}

namespace {

// The cells a channel must have values for: every slot's cell (the source's cells are the
// layout's).
std::size_t cellsNeeded(const VectorVolume& volume) {
  if (volume.cellIds.empty()) return 0;
  const std::span<const std::uint32_t> ids = volume.cellIds;
  return std::size_t(tbb::parallel_reduce(
             tbb::blocked_range<std::size_t>(0, ids.size()), std::uint32_t(0),
             [&](const tbb::blocked_range<std::size_t>& range, std::uint32_t most) {
               for (std::size_t i = range.begin(); i != range.end(); ++i)
                 most = std::max(most, ids[i]);
               return most;
             },
             [](std::uint32_t a, std::uint32_t b) { return std::max(a, b); })) +
         1;
}

// Gathers a channel's values into the slots (`store(slot, value)`), checking them against
// `bound` in the same pass. When the slots hold every value once (no periodic images, the whole
// input's cells) that checks them all; otherwise, and when one fails, checkChannelRange checks
// them in cell order and names the first.
template <typename Store>
void gatherChecked(const VectorVolume& volume, std::span<const float> values,
                   const std::string& source, const std::string& name, float bound,
                   const char* role, Store store) {
  const std::span<const std::uint32_t> ids = volume.cellIds;
  std::atomic<bool> outside = false;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size()), [&](const auto& range) {
    bool out = false;
    for (std::size_t slot = range.begin(); slot != range.end(); ++slot) {
      const float value = values[ids[slot]];
      out = out || !(std::abs(value) <= bound);
      store(slot, value);
    }
    if (out) outside = true;
  });
  if (outside || ids.size() != values.size()) checkChannelRange(values, source, name, bound, role);
}

void checkCount(std::size_t cellsNeeded, const std::string& name, std::span<const float> values) {
  if (values.size() < cellsNeeded)
    throw std::logic_error(
        fmt::format("fillVolumeValues: channel '{}' has {} values, fewer than the layout's {} "
                    "cells",
                    name, values.size(), cellsNeeded));
}

// The vector's values in brick order: its three channels, or its scalar's gradient.
void gatherVector(VectorVolume& volume, const VectorChannels& vector, const std::string& source,
                  const ChannelSource& channels, std::size_t cells) {
  const std::size_t slots = volume.cellIds.size();
  if (vector.isGradient()) {
    std::vector<float> scalars(slots);
    channels(vector.gradientOf, [&](std::span<const float> values) {
      checkCount(cells, vector.gradientOf, values);
      gatherChecked(volume, values, source, vector.gradientOf, kMaxPointDataValue,
                    "the scalar of the gradient",
                    [&](std::size_t slot, float value) { scalars[slot] = value; });
    });
    const std::vector<glm::vec3> gradients =
        physicalGradients(volume, scalars, vector.gradientSign, source, vector.gradientOf);
    tbb::parallel_for(std::size_t(0), slots,
                      [&](std::size_t slot) { volume.values[slot] = gradients[slot]; });
    return;
  }
  for (int c = 0; c < 3; ++c) {
    const std::string& name = vector.channels[c];
    if (name.empty()) {  // a 2D dataset's third component
      tbb::parallel_for(std::size_t(0), slots,
                        [&](std::size_t slot) { volume.values[slot][c] = 0.0f; });
      continue;
    }
    channels(name, [&](std::span<const float> values) {
      checkCount(cells, name, values);
      gatherChecked(volume, values, source, name, kMaxVectorComponent, "the vector component",
                    [&](std::size_t slot, float value) { volume.values[slot][c] = value; });
    });
  }
}

}  // namespace

void fillVolumeValues(VectorVolume& volume, const VectorChannels& vector,
                      const VolumeOptions& options, const std::string& source,
                      const ChannelSource& channels, VolumeBuildTimes* times) {
  Stopwatch clock;
  const std::size_t slots = volume.cellIds.size(), channelCount = options.pointData.size();
  // Every slot of both is written below (all three components, every channel).
  volume.values.clear();
  volume.values.resize(slots);
  volume.channelValues.clear();
  volume.channelValues.resize(slots * channelCount);
  const std::size_t cells = cellsNeeded(volume);
  gatherVector(volume, vector, source, channels, cells);
  volume.frameVelocity =
      options.autoFrame ? meanVector(volume, *options.autoFrame) : vector.frameVelocity;
  subtractFrameVelocity(volume, volume.frameVelocity);
  for (std::size_t c = 0; c < channelCount; ++c) {
    const std::string& name = options.pointData[c];
    channels(name, [&](std::span<const float> values) {
      checkCount(cells, name, values);
      gatherChecked(volume, values, source, name, kMaxPointDataValue, "the point-data channel",
                    [&](std::size_t slot, float value) {
                      volume.channelValues[slot * channelCount + c] = value;
                    });
    });
  }
  VolumeBuildTimes local = times ? *times : VolumeBuildTimes{};
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
}

std::vector<float> gatherScalar(const bricks::AmrField& field, const VectorVolume& volume,
                                std::string_view channel) {
  const Channel& source = field.channel(channel);
  std::vector<float> values(volume.cellIds.size());
  tbb::parallel_for(std::size_t(0), values.size(),
                    [&](std::size_t slot) { values[slot] = source.values[volume.cellIds[slot]]; });
  return values;
}

std::vector<std::string> choosePointData(const bricks::AmrField& field,
                                         const VectorChannels& vector, const std::string& request) {
  return choosePointData(catalogOf(field), vector, request);
}

std::vector<std::string> choosePointData(const ChannelCatalog& channels,
                                         const VectorChannels& vector, const std::string& request) {
  std::vector<std::string> names;
  if (request.empty() || request == "none") return names;
  if (request == "all") {
    for (const std::string& name : channels.names)
      if (std::find(vector.channels.begin(), vector.channels.end(), name) == vector.channels.end())
        names.push_back(name);
    return names;
  }
  std::stringstream list(request);
  for (std::string name; std::getline(list, name, ',');) {
    if (name.empty()) continue;
    if (!channels.has(name))
      throw settingError(
          "point_data",
          fmt::format("no channel '{}' in {}{}; the channels are: {}", name, channels.source,
                      didYouMean(name, channels.names), channels.list()));
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

}  // namespace amrstream::flow
