#pragma once
// Trace points as the kernels write them, in cell units or (VectorVolume::deepPositions) as
// offsets from their regions' corners, to physical coordinates: in double precision, as the CPU
// path computes them, then rounded to float (split into high and low parts when deep).

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>

#include "flow/vector_volume.hpp"

namespace amrstream::gpu {

// `ids` (the points' regions) and `low` are null unless the volume has deep positions.
void toPhysicalPositions(const flow::VectorVolume& volume, const glm::vec3* cells,
                         const std::int32_t* ids, std::size_t count, glm::vec3* high,
                         glm::vec3* low);

}  // namespace amrstream::gpu
