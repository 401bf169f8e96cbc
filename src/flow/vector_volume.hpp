#pragma once
// Everything the sampler reads, in the layout the GPU kernels also use: bricks, the vector
// values in brick order, the point-data channels in brick order, the regions with their kd-tree,
// the domain box and which of its axes are periodic.
//
// Periodic axes: positions wrap into the domain, and the tent sum near a periodic face must see
// the cells on the far side. So for every brick whose domain (its box padded by half a cell)
// reaches across a face, an image brick is added, shifted by the period, that shares the
// original's values (the same valueOffset); the regions are built over originals and images, so
// the sampler needs no other change. Images never create values and never hold seeds.

#include <array>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "bricks/amr_field.hpp"
#include "bricks/brick_builder.hpp"
#include "bricks/region_builder.hpp"
#include "column.hpp"
#include "vector_selection.hpp"

namespace amrstream::flow {

using PeriodicAxes = std::array<bool, 3>;

// How values between cell centres are reconstructed (docs/architecture.md): the paper's tent
// basis functions (continuous, exact for constants), or tent weights over each cell's linear
// model v_i + G_i (p - c_i), with G_i its least-squares gradient (continuous, exact for linear
// fields across any level jump).
enum class Interpolant { Tent, Linear };

struct VectorVolume {
  std::vector<shared::Brick> bricks;   // originals first, then periodic images
  std::size_t originalBrickCount = 0;  // bricks before the images
  // Columns: made without zeroing, so the threads that fill them touch their pages first.
  Column<glm::vec3> values;            // brick-ordered, see shared::Brick::valueOffset
  std::vector<std::uint32_t> cellIds;  // the field's cell at each value slot
  // Point data: scalar channels sampled along the traces, brick-ordered and interleaved:
  // channel c of slot s is channelValues[s * channelNames.size() + c].
  std::vector<std::string> channelNames;
  Column<float> channelValues;
  // Linear interpolant only: per slot, the gradients (per finest cell) of the vector's three
  // components, then of each channel (channelGradients[s * channelNames.size() + c]).
  Interpolant interpolant = Interpolant::Tent;
  std::vector<glm::vec3> vectorGradients;
  std::vector<glm::vec3> channelGradients;
  bricks::RegionSet regions;
  // Points outside the cells' bounding box [lower, upper) are out of the domain, even where the
  // half-cell padding of the brick domains reaches beyond it. Cell units are the field's, or,
  // when the field's reach beyond 2^20 of the origin, centred on the domain (buildCellLayout
  // moves the cells, and the transform with them).
  CellBox domain;
  // Whether the original bricks fill the domain box: no hole, every point of it in a cell.
  bool cellsFillDomain = false;
  PeriodicAxes periodic{};
  WorldTransform transform;
  std::string vectorName;
  // Planar data (DatasetInfo::dimensions 2): a slab across its plane, in which seeds are placed.
  bool planar = false;
  // The velocity of the frame the values are relative to, subtracted from the vector's values
  // (frame_velocity.hpp); zero for none.
  glm::dvec3 frameVelocity{0.0};

  glm::ivec3 period() const { return domain.upper - domain.lower; }
  // True for a point (cell units) in the domain box of a volume without holes, but not within
  // 2^-20 cells under an upper face: such a point is in a cell, and the region lookup, which
  // sees points rounded to float, finds its region. False says nothing.
  bool surelyInACell(glm::dvec3 cellUnits) const {
    constexpr double kUpperMargin = 0x1.0p-20;
    return cellsFillDomain &&
           glm::all(glm::greaterThanEqual(cellUnits, glm::dvec3(domain.lower))) &&
           glm::all(glm::lessThan(cellUnits, glm::dvec3(domain.upper) - kUpperMargin));
  }
  std::size_t channelCount() const { return channelNames.size(); }
  // Whether a float in cell units (centred on the domain) misses finest cells somewhere in the
  // domain: wider than 2^21 finest cells on some axis. The GPU then hands positions over as
  // offsets from their regions (line_state.h).
  bool deepPositions() const {
    const glm::ivec3 extent = period();
    return glm::any(glm::greaterThan(extent, glm::ivec3(1 << 21)));
  }
};

// Where frame_velocity auto takes the mean of the vector (frame_velocity.hpp), in the volume's
// cell units: the cells inside a box, each weighted by the volume of its part inside (along an
// axis where the box has no thickness, by whether it holds the box there: a plane's cells are
// weighted by their area on it); or, without a box, the cells that hold the points, each once,
// weighted by its volume.
struct FrameRegion {
  struct Box {
    glm::dvec3 lower, upper;
  };
  std::optional<Box> box;
  std::vector<glm::dvec3> points;
};

struct VolumeOptions {
  bricks::BrickBuildOptions bricks;
  // An MPI rank's part of the data: only the cells whose tents reach into this box (cell units,
  // after the centring of buildCellLayout) or its translates by a period along periodic axes
  // are kept, each brick cropped to them (bricks keep their order, their cells' order and the
  // whole field's domain and cell units, and images follow the kept bricks in their order, so
  // every sample in the box sums the same terms in the same order as the whole volume's).
  struct Box {
    glm::dvec3 lower, upper;
  };
  std::optional<Box> keepAround;
  PeriodicAxes periodic{};
  std::vector<std::string> pointData;  // channel names to sample along the traces
  Interpolant interpolant = Interpolant::Tent;
  // frame_velocity auto: the frame's velocity is the vector's mean over this region, not the
  // vector's frameVelocity.
  std::optional<FrameRegion> autoFrame;
};

// The shifts of -1, 0 or +1 periods along each periodic axis (none along the others), the zero
// shift first.
std::vector<glm::ivec3> periodicShifts(const PeriodicAxes& periodic);

struct VolumeBuildTimes {
  double bricks = 0.0;  // seconds
  double regions = 0.0;
  double gather = 0.0;
  double gradients = 0.0;  // linear interpolant only
};

// The cells' layout alone: the bricks (with the images across `options.periodic` axes), their
// regions, the cell of each value slot, the domain and the transform; no values, so it locates
// points (insideACell, randomSeedsInCells) but cannot be sampled. buildVectorVolume starts here.
VectorVolume buildCellLayout(const bricks::AmrField& field, const VolumeOptions& options = {},
                             VolumeBuildTimes* times = nullptr);

// Throws InputError (listing the channels) when a point-data channel is absent.
// The layout buildCellLayout makes with `options` from the cells `whole` was built from (with
// the same brick options, all of them kept), made from whole's bricks instead of the cells:
// for an MPI rank's part (options.keepAround).
VectorVolume cropCellLayout(const VectorVolume& whole, const VolumeOptions& options,
                            VolumeBuildTimes* times = nullptr);

VectorVolume buildVectorVolume(const bricks::AmrField& field, const VectorChannels& vector,
                               const VolumeOptions& options = {},
                               VolumeBuildTimes* times = nullptr);

// Gives a channel's values in cell order (one per cell of the layout's field) to the function
// it is passed, once; they may be read from a file then and freed after (formats::readExaCells),
// so that one channel at a time is in memory beside the volume.
using ChannelUse = std::function<void(std::span<const float> values)>;
using ChannelSource = std::function<void(const std::string& name, const ChannelUse& use)>;

// What buildVectorVolume does after buildCellLayout: the vector's values (its three channels,
// or its scalar's gradient: gradient_vector.hpp) and the point data (options.pointData)
// gathered into brick order from `channels`, checked against the float32 bounds
// (value_range.hpp; errors name `source`), less the frame velocity (the vector's, or with
// options.autoFrame the mean over that region: frame_velocity.hpp), then the linear
// interpolant's gradients. The same volume as buildVectorVolume's from a field with those values.
void fillVolumeValues(VectorVolume& volume, const VectorChannels& vector,
                      const VolumeOptions& options, const std::string& source,
                      const ChannelSource& channels, VolumeBuildTimes* times = nullptr);
// The same from the channels of `field`, the cells the layout was made from; InputError before
// anything is filled when one is absent.
void fillVolumeValues(VectorVolume& volume, const bricks::AmrField& field,
                      const VectorChannels& vector, const VolumeOptions& options,
                      VolumeBuildTimes* times = nullptr);

// A scalar channel of `field` in the volume's brick order, for sampleScalar() and the renderer.
// Throws InputError listing the channels when `channel` is absent.
std::vector<float> gatherScalar(const bricks::AmrField& field, const VectorVolume& volume,
                                std::string_view channel);

// The point-data channels a request names: "all" (every channel but the vector's three), "none"
// (or empty), or a comma-separated list. Throws InputError naming an unknown channel and listing
// the available ones.
std::vector<std::string> choosePointData(const bricks::AmrField& field,
                                         const VectorChannels& vector, const std::string& request);
std::vector<std::string> choosePointData(const ChannelCatalog& channels,
                                         const VectorChannels& vector, const std::string& request);

}  // namespace amrstream::flow
