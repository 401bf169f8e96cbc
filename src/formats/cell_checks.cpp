#include "formats/cell_checks.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "amrstream/error.hpp"
#include "bricks/amr_field.hpp"

namespace amrstream::formats {

namespace {

// The cells' bounding box in finest-cell units, with each cell's upper corner at lower +
// 2^level (exact in double for the 32-bit corners and levels up to 255), and the first cell whose
// level passes bricks::kMaxLevel or whose upper corner passes 2^31 - 1 (the count when none).
// Computed in parallel: min and max are exact, so the box is that of one pass in order.
struct CellsBox {
  glm::dvec3 lower{std::numeric_limits<double>::infinity()};
  glm::dvec3 upper{-std::numeric_limits<double>::infinity()};
  std::size_t firstOutside;
};

CellsBox cellsBox(std::span<const glm::ivec3> lowers, std::span<const std::uint8_t> levels) {
  static const std::array<double, 256> widths = [] {
    std::array<double, 256> w{};
    for (int level = 0; level < 256; ++level) w[std::size_t(level)] = std::ldexp(1.0, level);
    return w;
  }();
  const std::size_t n = std::min(lowers.size(), levels.size());
  constexpr double kIntMax = std::numeric_limits<std::int32_t>::max();
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n), CellsBox{.firstOutside = n},
      [&](const tbb::blocked_range<std::size_t>& range, CellsBox box) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          const glm::dvec3 corner(lowers[i]);
          const glm::dvec3 end = corner + widths[levels[i]];
          if (i < box.firstOutside && (levels[i] > bricks::kMaxLevel ||
                                       glm::any(glm::greaterThan(end, glm::dvec3(kIntMax)))))
            box.firstOutside = i;
          box.lower = glm::min(box.lower, corner);
          box.upper = glm::max(box.upper, end);
        }
        return box;
      },
      [](CellsBox a, const CellsBox& b) {
        a.lower = glm::min(a.lower, b.lower);
        a.upper = glm::max(a.upper, b.upper);
        a.firstOutside = std::min(a.firstOutside, b.firstOutside);
        return a;
      });
}

// Why `transform` cannot place cells in `box`; with `noCells`, only the origin and spacing.
std::optional<std::string> positionsProblem(const WorldTransform& transform, const CellsBounds& box,
                                            bool noCells) {
  for (int a = 0; a < 3; ++a) {
    const double origin = transform.origin[a], spacing = transform.spacing[a];
    const char axis = "xyz"[a];
    if (!std::isfinite(origin)) return fmt::format("the origin along {} is {}", axis, origin);
    if (!(spacing >= kMinSpacing && spacing <= kMaxPositionMagnitude))
      return fmt::format(
          "the spacing along {} is {}, outside the [{}, {}] that float32 "
          "positions can hold",
          axis, spacing, kMinSpacing, kMaxPositionMagnitude);
    const double lower = box.lower[a], upper = box.upper[a];
    if (noCells) continue;
    const double low = origin + spacing * lower, high = origin + spacing * upper;
    const double largest = std::max(std::abs(low), std::abs(high));
    if (!(largest <= kMaxPositionMagnitude))
      return fmt::format(
          "origin {} + spacing {} x cell units [{}, {}] along {} reaches {}, "
          "beyond the {} that float32 positions can hold",
          origin, spacing, lower, upper, axis, largest, kMaxPositionMagnitude);
    if (!(spacing > 4 * largest * std::numeric_limits<double>::epsilon()))
      return fmt::format(
          "origin {} + spacing {} x cell units [{}, {}] along {} reaches {}, where "
          "positions cannot resolve a finest cell: neighbouring cells would share "
          "a position",
          origin, spacing, lower, upper, axis, largest);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> unusableFieldValue(double value) {
  if (std::isnan(value)) return "not a number";
  if (std::isinf(value)) return "infinite";
  if (std::abs(value) > kLargestFieldValue) return "beyond the float range";
  return std::nullopt;
}

CellsBounds requireCellsWithinExtent(std::span<const glm::ivec3> lowers,
                                     std::span<const std::uint8_t> levels,
                                     const std::string& source) {
  if (std::min(lowers.size(), levels.size()) == 0) return {};
  const CellsBox box = cellsBox(lowers, levels);
  if (const std::size_t i = box.firstOutside; i < std::min(lowers.size(), levels.size())) {
    if (levels[i] > bricks::kMaxLevel)
      throw InputError(source, fmt::format("cell {} has level {}, above the supported {}", i,
                                           levels[i], bricks::kMaxLevel));
    throw InputError(source, fmt::format("cell {} at ({}, {}, {}), {} finest cells wide, "
                                         "reaches past 2^31 - 1",
                                         i, lowers[i].x, lowers[i].y, lowers[i].z,
                                         std::int64_t{1} << levels[i]));
  }
  const glm::i64vec3 lower(box.lower), upper(box.upper);
  const glm::i64vec3 extent = upper - lower;
  const std::int64_t limit = std::int64_t{1} << bricks::kMaxExtentBits;
  for (int a = 0; a < 3 && !lowers.empty(); ++a)
    if (extent[a] > limit)
      throw InputError(source, fmt::format("the cells span {} finest cells along axis {} (from {} "
                                           "to {}); at most {} are supported",
                                           extent[a], "xyz"[a], lower[a], upper[a], limit));
  return {box.lower, box.upper};
}

std::optional<std::string> unrepresentablePositions(const WorldTransform& transform,
                                                    std::span<const glm::ivec3> lowers,
                                                    std::span<const std::uint8_t> levels) {
  const CellsBox box = cellsBox(lowers, levels);
  return positionsProblem(transform, {box.lower, box.upper}, lowers.empty());
}

std::optional<std::string> unrepresentablePositions(const WorldTransform& transform,
                                                    const CellsBounds& bounds) {
  return positionsProblem(transform, bounds, false);
}

}  // namespace amrstream::formats
