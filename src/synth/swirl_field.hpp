#pragma once
// An unsteady flow for pathlines: rotation about the vertical axis through (0.5, 0.5) at a
// pulsing rate, plus a vertical drift that reverses,
//     v(x, t) = W(t) e_z x (x - c) + (0, 0, w(t)),  W(t) = 2 pi (1 + 0.5 sin 2 pi t),
//     w(t) = 0.1 cos 2 pi t,
// and a scalar "temp" = 1 + 0.5 z + 0.25 t, linear in space and time. A particle's path is known
// in closed form: its angle about the axis turns by A(t) - A(t0) with A(t) = 2 pi t + 0.5 (1 -
// cos 2 pi t), its height moves by Z(t) - Z(t0) with Z(t) = 0.1 sin(2 pi t) / (2 pi).
//
// Refinement follows a feature carried by the flow (the particle released at (0.75, 0.5, 0.5) at
// t = 0): priority w / (d + w) for a block of cell width w at distance d from it, so the refined
// region moves from snapshot to snapshot and the level of a place changes with time.

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <numbers>

#include "block_refiner.hpp"

namespace amrstream::synth {

struct SwirlField {
  static constexpr double kTwoPi = 2.0 * std::numbers::pi;
  static constexpr glm::dvec3 kFeatureStart{0.75, 0.5, 0.5};

  static double rate(double t) { return kTwoPi * (1.0 + 0.5 * std::sin(kTwoPi * t)); }
  static double drift(double t) { return 0.1 * std::cos(kTwoPi * t); }
  static double turned(double t) { return kTwoPi * t + 0.5 * (1.0 - std::cos(kTwoPi * t)); }
  static double risen(double t) { return 0.1 * std::sin(kTwoPi * t) / kTwoPi; }

  static glm::dvec3 velocity(glm::dvec3 p, double t) {
    const double w = rate(t);
    return {-w * (p.y - 0.5), w * (p.x - 0.5), drift(t)};
  }

  static double temperature(glm::dvec3 p, double t) { return 1.0 + 0.5 * p.z + 0.25 * t; }

  // Where the particle at p at time t0 is at time t.
  static glm::dvec3 pathline(glm::dvec3 p, double t0, double t) {
    const double angle = turned(t) - turned(t0);
    const double c = std::cos(angle), s = std::sin(angle);
    const double x = p.x - 0.5, y = p.y - 0.5;
    return {0.5 + c * x - s * y, 0.5 + s * x + c * y, p.z + risen(t) - risen(t0)};
  }

  static double refinementPriority(const BlockBox& box, double t) {
    const glm::dvec3 feature = pathline(kFeatureStart, 0.0, t);
    const glm::dvec3 outside = glm::max(glm::max(box.lower - feature, feature - box.upper), 0.0);
    return box.cellWidth / (glm::length(outside) + box.cellWidth);
  }
};

}  // namespace amrstream::synth
