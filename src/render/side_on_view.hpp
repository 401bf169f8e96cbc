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

// The camera turned to see `segments` side on: the view from above along the up axis (the next
// axis to the right) where hardly any of their length runs along the up axis (lines across it,
// as in 2D data); else, where the view it has runs at least kSideOnGain more along them than the
// best side view, of the azimuths every 5 degrees at its elevation that run at most kSideOnSlack
// more along them than the best, the one nearest its azimuth (some depth shows).
constexpr float kSideOnGain = 0.1f;
constexpr float kSideOnSlack = 0.05f;
OrbitCamera sideOn(OrbitCamera camera, std::span<const shared::TubeSegment> segments);

}  // namespace amrstream::render
