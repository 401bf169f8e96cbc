#pragma once
// A vector relative to a moving frame: the frame's velocity subtracted from every value, and the
// velocity `auto` gives the frame, the mean of the vector over a region weighted by cell volume.

#include <glm/glm.hpp>

#include "vector_volume.hpp"

namespace amrstream::flow {

// The weighted mean of the volume's vector values over the region (FrameRegion says how each
// cell is weighted), summed in the bricks' order
// whatever the threads (every process of an MPI job finds the same bits). Throws InputError
// naming {frame_velocity} when the region holds no cell.
glm::dvec3 meanVector(const VectorVolume& volume, const FrameRegion& region);

// Subtracts `frame` from every vector value (rounded to float once per component).
void subtractFrameVelocity(VectorVolume& volume, glm::dvec3 frame);

}  // namespace amrstream::flow
