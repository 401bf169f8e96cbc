#pragma once
// The range that holds the middle of the tubes' colour values, for a colour map that a few
// outliers would otherwise squeeze into one colour.

#include <optional>
#include <span>

#include "../../shaders/glsl/shared/render_types.h"
#include "tube_geometry.hpp"

namespace amrstream::render {

// From the `low` to the `high` quantile of the segments' end values (scale coordinates, as the
// tubes carry them), over at most kMiddleRangeSamples evenly strided segments; outline segments
// and values that are not finite are left out. nullopt when fewer than two distinct values remain.
inline constexpr std::size_t kMiddleRangeSamples = std::size_t{1} << 16;
std::optional<ValueRange> middleRange(std::span<const shared::TubeSegment> segments, double low,
                                      double high);

}  // namespace amrstream::render
