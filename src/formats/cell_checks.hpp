#pragma once
// Checks the readers make on cells and values before they become a bricks::AmrField: values a
// float channel can hold, and cell corners whose extent fits the integer arithmetic of the field
// (corners near INT_MAX would overflow it).

#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include "bricks/amr_field.hpp"

namespace amrstream::formats {

// Positions are written as float32: they and the spacing must lie in float's normal range (as
// bricks::AmrField requires too; the readers check first to name the file and its entries).
inline constexpr double kMaxPositionMagnitude = 1e37;
inline constexpr double kMinSpacing = std::numeric_limits<float>::min();

// 2D data is held as a slab across z = 0 as thick as its coarsest leaf cell: a finer cell repeats
// along z. At most this many cells per leaf cell of the file (leaves 8 levels finer than the
// coarsest, at most), so that the cells stay within a small multiple of the data stored.
inline constexpr std::size_t kMaxSlabGrowth = 256;

// Why `value` cannot be a float channel value ("not a number", "infinite", "beyond the float
// range"), or nullopt when it can.
std::optional<std::string> unusableFieldValue(double value);
// Every value whose magnitude is at most this (NaN is not) is usable: the test a reader makes
// per value before it asks unusableFieldValue why one is not.
inline constexpr double kLargestFieldValue = std::numeric_limits<float>::max();

// The cells' bounding box in finest-cell units (upper corners at lower + 2^level).
struct CellsBounds {
  glm::dvec3 lower{0.0};
  glm::dvec3 upper{0.0};
};

// Throws InputError(source, ...) naming the first cell whose upper corner (lower + 2^level) does
// not fit in 32 bits, or the extent of the cells when their bounding box spans 2^kMaxExtentBits
// finest cells or more along an axis. Levels must be at most bricks::kMaxLevel. Returns the
// box, for unrepresentablePositions.
CellsBounds requireCellsWithinExtent(std::span<const glm::ivec3> lowers,
                                     std::span<const std::uint8_t> levels,
                                     const std::string& source);

// Why `transform` cannot place the cells, or nullopt when it can: its origin is not finite, a
// spacing lies outside [kMinSpacing, kMaxPositionMagnitude], a corner of the cells' bounding box
// lies beyond kMaxPositionMagnitude, or a finest cell is too small for positions there to tell
// neighbouring cells apart. The reason names the axis and the numbers.
std::optional<std::string> unrepresentablePositions(const WorldTransform& transform,
                                                    std::span<const glm::ivec3> lowers,
                                                    std::span<const std::uint8_t> levels);
// The same for the bounding box of at least one cell.
std::optional<std::string> unrepresentablePositions(const WorldTransform& transform,
                                                    const CellsBounds& bounds);

}  // namespace amrstream::formats
