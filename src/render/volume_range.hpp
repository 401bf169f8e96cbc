#pragma once
// The default transfer-function range of a context scalar: from the median to the 99.9th
// percentile of its cells' values (of log10 of them when `logarithmic`, over positive values),
// so the densest structures stand out and the bulk stays transparent.

#include <span>

#include "tube_geometry.hpp"

namespace amrstream::render {

ValueRange defaultVolumeRange(std::span<const float> values, bool logarithmic);

}  // namespace amrstream::render
