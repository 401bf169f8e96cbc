#pragma once
// One filament of the synthetic cloud: a cubic Bezier spine and the parameters of its two
// density tubes (a narrow core and a wide envelope) and of the magnetic field wrapped around it.

#include <array>
#include <glm/glm.hpp>

namespace amrstream::synth {

struct Filament {
  std::array<glm::dvec3, 4> controls{};  // Bezier control points of the spine
  double coreRadius = 0.0;               // support radius of the core kernel
  double envelopeRadius = 0.0;           // support radius of the envelope kernel
  double coreDensity = 0.0;              // density the core adds on a straight spine
  double envelopeDensity = 0.0;          // density the envelope adds on a straight spine
  double coreWrap = 0.0;                 // signed peak azimuthal field of the core, straight spine
  double envelopeWrap = 0.0;             // same for the envelope

  glm::dvec3 pointAt(double t) const {
    const double s = 1.0 - t;
    return s * s * s * controls[0] + 3.0 * s * s * t * controls[1] + 3.0 * s * t * t * controls[2] +
           t * t * t * controls[3];
  }

  glm::dvec3 tangentAt(double t) const {  // dC/dt, not normalised
    const double s = 1.0 - t;
    return 3.0 * s * s * (controls[1] - controls[0]) + 6.0 * s * t * (controls[2] - controls[1]) +
           3.0 * t * t * (controls[3] - controls[2]);
  }
};

}  // namespace amrstream::synth
