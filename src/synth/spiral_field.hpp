#pragma once
// A steady spiral about a centre c: rotation about the vertical axis through c plus a uniform
// expansion away from c,
//     v(x) = omega e_z x d + alpha d,  d = x - c,
// so a streamline turns about the axis at omega radians per unit time while its offset from c
// grows as exp(alpha t): d(t) = exp(alpha t) R_z(omega t) d(0). The field depends on d alone,
// which callers near a deep nest's centre know more precisely than x and c (nest_generator.hpp).

#include <cmath>
#include <glm/glm.hpp>

namespace amrstream::synth {

struct SpiralField {
  double rotationRate = 0.0;   // omega, radians per unit time
  double expansionRate = 0.0;  // alpha, per unit time

  glm::dvec3 velocity(glm::dvec3 d) const {
    return {expansionRate * d.x - rotationRate * d.y, rotationRate * d.x + expansionRate * d.y,
            expansionRate * d.z};
  }

  // The offset from c, after time t, of the streamline through offset d.
  glm::dvec3 offsetAfter(glm::dvec3 d, double t) const {
    const double angle = rotationRate * t, growth = std::exp(expansionRate * t);
    const double cosine = std::cos(angle), sine = std::sin(angle);
    return growth * glm::dvec3(cosine * d.x - sine * d.y, sine * d.x + cosine * d.y, d.z);
  }
};

}  // namespace amrstream::synth
