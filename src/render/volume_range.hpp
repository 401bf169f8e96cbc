#pragma once
// The volume's default transfer function, chosen from the histogram of its scalar over the cells,
// each cell counted by the space it fills (8^level finest cells) as ParaView's default transfer
// function spans the data: the range from the value most of the domain holds (the median by
// space, so the bulk stays clear) to the 99.9th percentile by cells (the densest structures, which
// refinement resolves in many cells), and the opacity that absorbs a ray across the domain to
// 1 - 1/e on average, whatever the resolution and however small the structures.

#include <span>

#include "flow/vector_volume.hpp"
#include "tube_geometry.hpp"

namespace amrstream::render {

// `values`: the scalar in `volume`'s brick order (flow::gatherScalar); log10 of the positive
// ones when `logarithmic`. A range of width 1 above the median where the values are all equal;
// the empty range where no value counts.
ValueRange defaultVolumeRange(const flow::VectorVolume& volume, std::span<const float> values,
                              bool logarithmic);

// The extinction per finest cell at the top of `range` (TubeRenderSettings::volumeOpacity) under
// which the mean optical depth across the domain, along an axis, is 1: the renderer's extinction
// is opacity x^2 per finest cell at x in [0, 1] along the range, so this is 1 / (the mean of x^2
// over the domain's space times the domain's mean width in finest cells). kFallbackOpacity where
// no value lies above the range's bottom.
float defaultVolumeOpacity(const flow::VectorVolume& volume, std::span<const float> values,
                           bool logarithmic, ValueRange range);

inline constexpr float kFallbackOpacity = 0.05f;

}  // namespace amrstream::render
