#pragma once
// The values of a gradient vector (gradient_request.hpp): at every value slot, the gradient of a
// scalar fitted to the cell's face neighbours as the linear interpolant's gradients are
// (cell_gradients.hpp: exact for a linear scalar across any level jump and periodic face),
// converted to a gradient per physical length along each of the input's axes.

#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

#include "vector_volume.hpp"

namespace amrstream::flow {

// `scalars`: one per value slot of the volume's layout. Returns sign * (dS/dx, dS/dy, dS/dz) per
// slot, x, y and z the input's physical coordinates (volume.transform). Throws InputError naming
// `source` and the scalar where a component passes kMaxVectorComponent (value_range.hpp).
std::vector<glm::vec3> physicalGradients(const VectorVolume& volume, std::span<const float> scalars,
                                         float sign, const std::string& source,
                                         const std::string& scalar);

}  // namespace amrstream::flow
