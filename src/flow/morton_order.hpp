#pragma once
// Spatial order (GPU threads, MPI ranks' shares of the seeds): points sorted by the Morton code of
// their position on a 1024^3 grid over their bounding box, so that neighbouring threads start near
// each other.

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace amrstream::flow {

// The points' indices in Morton order (parallel sort; ties keep index order).
std::vector<std::uint32_t> mortonOrder(std::span<const glm::vec3> points);

}  // namespace amrstream::flow
