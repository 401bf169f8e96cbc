#pragma once
// Least-squares gradients of cell values, for the linear interpolant (docs/architecture.md,
// "The linear interpolant"): at every value slot, the gradient that best fits the differences
// to the cell's face neighbours (one cell over along each axis, in either direction), whichever
// brick, level or periodic image holds them. Exact for linear fields: any set of neighbours that
// spans the three axes fits a linear field without residual.

#include <cstddef>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "vector_volume.hpp"

namespace amrstream::flow {

// `values` holds `components` floats per slot (slot-major, as VectorVolume::channelValues);
// returns `components` gradients per slot, in values per finest cell, in the same order.
std::vector<glm::vec3> cellGradients(const VectorVolume& volume, std::span<const float> values,
                                     std::size_t components);

}  // namespace amrstream::flow
