#pragma once
// Solid-body rotation about the z axis through the domain centre c = (0.5, 0.5, 0.5):
// v(x) = omega x (x - c) with omega = (0, 0, 2 pi), one revolution per unit time, so every
// streamline is a horizontal circle about the axis and |v| = 2 pi * (distance to the axis).
//
// Refinement follows the ring of radius 0.25 about the axis in the plane z = 0.5 (itself a
// streamline): priority = w / (d + w) for a block of cell width w at distance d from the ring,
// so the cell width grows in proportion to the distance from the ring (nested shells of levels).

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <numbers>

#include "block_refiner.hpp"

namespace amrstream::synth {

struct RotationField {
  static constexpr double kOmega = 2.0 * std::numbers::pi;
  static constexpr glm::dvec3 kCentre{0.5, 0.5, 0.5};
  static constexpr double kRingRadius = 0.25;

  static glm::dvec3 velocity(glm::dvec3 p) {
    const glm::dvec3 r = p - kCentre;
    return {-kOmega * r.y, kOmega * r.x, 0.0};
  }

  static double distanceToRing(glm::dvec3 p) {
    const glm::dvec3 r = p - kCentre;
    const double radial = std::sqrt(r.x * r.x + r.y * r.y) - kRingRadius;
    return std::sqrt(radial * radial + r.z * r.z);
  }

  // Exact: a box's (distance to the axis, height) pairs fill the product of their two ranges.
  static double distanceToRing(const BlockBox& box) {
    const glm::dvec3 lower = box.lower - kCentre, upper = box.upper - kCentre;
    const auto nearest = [](double lo, double hi) { return std::max({lo, -hi, 0.0}); };
    const auto farthest = [](double lo, double hi) { return std::max(-lo, hi); };
    const double dz = nearest(lower.z, upper.z);
    const double axisNear = std::hypot(nearest(lower.x, upper.x), nearest(lower.y, upper.y));
    const double axisFar = std::hypot(farthest(lower.x, upper.x), farthest(lower.y, upper.y));
    const double dr = std::max({axisNear - kRingRadius, kRingRadius - axisFar, 0.0});
    return std::hypot(dr, dz);
  }

  static double refinementPriority(const BlockBox& box) {
    return box.cellWidth / (distanceToRing(box) + box.cellWidth);
  }
};

}  // namespace amrstream::synth
