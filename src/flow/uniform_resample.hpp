#pragma once
// The reconstructed field on a uniform grid of points, as ParaView's Resample To Image makes it:
// the vector and the point-data channels sampled (tent or linear interpolant, as the volume says)
// at the centres of NX x NY x NZ equal cells of a box, with a mask of the points where the
// sample is valid (inside the domain, in a region, weights above kMinWeightSum).

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "cell_point.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

struct UniformGridSpec {
  glm::dvec3 lower{0.0}, upper{1.0};  // physical box
  std::array<std::uint32_t, 3> dims{1, 1, 1};

  glm::dvec3 spacing() const { return (upper - lower) / glm::dvec3(dims[0], dims[1], dims[2]); }
  glm::dvec3 origin() const { return lower + 0.5 * spacing(); }  // the first point
  std::uint64_t pointCount() const { return std::uint64_t(dims[0]) * dims[1] * dims[2]; }
};

// The grid of `dims` points per axis (three counts, or one for the box's longest axis and the
// others in proportion, at least 1) over `box` (lower x, y, z, upper x, y, z; empty: the domain).
// Throws InputError naming --dims or --box for counts outside 1..65535, a wrong number of them,
// or a box whose upper corner is not above its lower one, and naming --dims when the grid would
// not fit in 3/4 of the machine's memory (13 bytes a point and 4 more per channel).
UniformGridSpec uniformGridSpec(const VectorVolume& volume, std::span<const std::uint64_t> dims,
                                std::span<const double> box = {});
// The counts' checks alone, before there is a volume.
void checkGridCounts(std::span<const std::uint64_t> dims);

// Points origin + i steps[0] + j steps[1] + k steps[2] (physical), for i, j, k below dims: a
// uniform grid, or a slice's pixel centres on a plane of any direction.
struct AffineGrid {
  glm::dvec3 origin{0.0};
  std::array<glm::dvec3, 3> steps{glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)};
  std::array<std::uint32_t, 3> dims{1, 1, 1};

  std::uint64_t pointCount() const { return std::uint64_t(dims[0]) * dims[1] * dims[2]; }
};

struct GridSamples {
  // Point (i, j, k) is i + NX (j + NY k). Invalid points hold zeros.
  std::vector<glm::vec3> vectors;
  std::vector<float> channels;  // interleaved: channel c of point n at n * channelCount + c
  std::vector<std::uint8_t> valid;
  std::uint64_t validCount = 0;
};

struct UniformGrid : GridSamples {
  UniformGridSpec spec;
};

// `volume` sampled at pointAt(i, row) for i below rowLength and row below rows, into point
// i + rowLength row, on all cores, a row at a time; `progress(done)` is called from one thread at
// a time with the number of rows done.
GridSamples sampleRows(const VectorVolume& volume, std::size_t rowLength, std::size_t rows,
                       const std::function<CellPoint(std::size_t, std::size_t)>& pointAt,
                       const std::function<void(std::size_t)>& progress = {});

// Samples `volume` at every point of `grid` on all cores; `progress(done)` is called from one
// thread at a time with the number of rows of points done (of dims[1] * dims[2]).
GridSamples sampleGrid(const VectorVolume& volume, const AffineGrid& grid,
                       const std::function<void(std::size_t)>& progress = {});

// sampleGrid at the points of `spec`.
UniformGrid resampleUniform(const VectorVolume& volume, const UniformGridSpec& spec,
                            const std::function<void(std::size_t)>& progress = {});

}  // namespace amrstream::flow
