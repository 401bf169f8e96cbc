#pragma once
// Arnold-Beltrami-Childress flow with A = sqrt(3), B = sqrt(2), C = 1, on the unit cube mapped
// to [0, 2 pi]^3 (X = 2 pi x):
//   v = (A sin Z + C cos Y,  B sin X + A cos Z,  C sin Y + B cos X)
// The values are those of the formula in X units; the mapping only rescales the speed, so the
// streamlines are the ABC ones. The flow is a Beltrami field (curl v = v in X units).
//
// Refinement follows the stagnation points (e.g. x = (1/4, 1/2, (pi - asin(1/sqrt 3)) / (2 pi))),
// where streamlines are most sensitive. The speed is Lipschitz with constant
// L = 2 pi sqrt(A^2 + B^2 + C^2) (the Frobenius norm of the velocity gradient is constant), so a
// point of speed s is at least s / L from any stagnation point. A block's distance is estimated
// as d = (least speed on a 3x3x3 lattice over the block) / L, and priority = w / (d + w) for cell
// width w: nested shells of levels around the stagnation points.

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <numbers>

#include "block_refiner.hpp"

namespace amrstream::synth {

struct AbcField {
  static constexpr double kA = std::numbers::sqrt3;
  static constexpr double kB = std::numbers::sqrt2;
  static constexpr double kC = 1.0;
  // Every component is 2 pi-periodic in X, Y and Z, and the unit cube maps to exactly one period.
  static constexpr bool kPeriodic = true;

  static glm::dvec3 velocity(glm::dvec3 p) {
    const glm::dvec3 x = 2.0 * std::numbers::pi * p;
    return {kA * std::sin(x.z) + kC * std::cos(x.y), kB * std::sin(x.x) + kA * std::cos(x.z),
            kC * std::sin(x.y) + kB * std::cos(x.x)};
  }

  static double refinementPriority(const BlockBox& box) {
    const double lipschitz = 2.0 * std::numbers::pi * std::sqrt(kA * kA + kB * kB + kC * kC);
    double slowest = std::numeric_limits<double>::max();
    for (int i = 0; i < 27; ++i) {
      const glm::dvec3 t(i % 3, i / 3 % 3, i / 9);
      slowest =
          std::min(slowest, glm::length(velocity(box.lower + 0.5 * t * (box.upper - box.lower))));
    }
    const double d = slowest / lipschitz;
    return box.cellWidth / (d + box.cellWidth);
  }
};

}  // namespace amrstream::synth
