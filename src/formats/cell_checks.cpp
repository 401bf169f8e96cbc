#include "cell_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "bricks/amr_field.hpp"
#include "util/input_error.hpp"

namespace amrstream::formats {

std::optional<std::string> unusableFieldValue(double value) {
  if (std::isnan(value)) return "not a number";
  if (std::isinf(value)) return "infinite";
  if (std::abs(value) > std::numeric_limits<float>::max()) return "beyond the float range";
  return std::nullopt;
}

void requireCellsWithinExtent(std::span<const glm::ivec3> lowers,
                              std::span<const std::uint8_t> levels, const std::string& source) {
  constexpr std::int64_t kIntMax = std::numeric_limits<std::int32_t>::max();
  glm::i64vec3 lower(std::numeric_limits<std::int64_t>::max());
  glm::i64vec3 upper(std::numeric_limits<std::int64_t>::min());
  for (std::size_t i = 0; i < lowers.size() && i < levels.size(); ++i) {
    if (levels[i] > bricks::kMaxLevel)
      throw InputError(source, fmt::format("cell {} has level {}, above the supported {}", i,
                                           levels[i], bricks::kMaxLevel));
    const glm::i64vec3 corner(lowers[i]);
    const std::int64_t width = std::int64_t{1} << levels[i];
    const glm::i64vec3 end = corner + width;
    if (glm::any(glm::greaterThan(end, glm::i64vec3(kIntMax))))
      throw InputError(source, fmt::format("cell {} at ({}, {}, {}), {} finest cells wide, "
                                           "reaches past 2^31 - 1",
                                           i, corner.x, corner.y, corner.z, width));
    lower = glm::min(lower, corner);
    upper = glm::max(upper, end);
  }
  const glm::i64vec3 extent = upper - lower;
  const std::int64_t limit = std::int64_t{1} << bricks::kMaxExtentBits;
  for (int a = 0; a < 3 && !lowers.empty(); ++a)
    if (extent[a] > limit)
      throw InputError(source, fmt::format("the cells span {} finest cells along axis {} (from {} "
                                           "to {}); at most {} are supported",
                                           extent[a], "xyz"[a], lower[a], upper[a], limit));
}

std::optional<std::string> unrepresentablePositions(const bricks::WorldTransform& transform,
                                                    std::span<const glm::ivec3> lowers,
                                                    std::span<const std::uint8_t> levels) {
  for (int a = 0; a < 3; ++a) {
    const double origin = transform.origin[a], spacing = transform.spacing[a];
    const char axis = "xyz"[a];
    if (!std::isfinite(origin)) return fmt::format("the origin along {} is {}", axis, origin);
    if (!(spacing >= kMinSpacing && spacing <= kMaxPositionMagnitude))
      return fmt::format(
          "the spacing along {} is {}, outside the [{}, {}] that float32 "
          "positions can hold",
          axis, spacing, kMinSpacing, kMaxPositionMagnitude);
    double lower = std::numeric_limits<double>::infinity(), upper = -lower;
    for (std::size_t i = 0; i < lowers.size() && i < levels.size(); ++i) {
      lower = std::min(lower, double(lowers[i][a]));
      upper = std::max(upper, double(lowers[i][a]) + std::ldexp(1.0, levels[i]));
    }
    if (lowers.empty()) continue;
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

}  // namespace amrstream::formats
