#pragma once
// The default direction to look at traces from: side on, across the lines rather than along
// them, so that a bundle of lines running one way shows as lines and not as a blob.

#include <span>

#include "../../shaders/glsl/shared/render_types.h"
#include "camera.hpp"

namespace amrstream::render {

// How much of the segments' length runs along a unit direction, from 0 (all across it) to 1
// (all along it): d^T T d / trace(T) for T, the sum over segments of length x the outer product
// of its unit direction. 0 for no segments.
float lengthAlong(std::span<const shared::TubeSegment> segments, glm::vec3 direction);

// The camera turned to see `segments` side on: among the azimuths (every 5 degrees) at its
// elevation, the one whose view runs least along the segments, or the view from above along the
// up axis (the next axis to the right) where that runs hardly more along them (lines across the
// up axis, as in 2D data). The camera keeps its direction unless that runs at least kSideOnGain
// more along them.
constexpr float kSideOnGain = 0.1f;
OrbitCamera sideOn(OrbitCamera camera, std::span<const shared::TubeSegment> segments);

}  // namespace amrstream::render
