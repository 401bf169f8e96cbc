#pragma once
// A magnetised filament cloud in the unit cube, resembling a molecular-cloud zoom simulation
// (SILCC-Zoom): 4 to 8 dense curved filaments around a common hub, with a magnetic field that
// threads through them and wraps around them. Code units: background density 1, mean field 1.
//
// Every filament is a cubic Bezier spine C(t), discretised into short chords (midpoint m_k,
// chord vector dc_k, at most R/4 long) and smoothed by the compact kernel
//   W(x) = (1 - |x|^2 / R^2)^6 for |x| < R, else 0  (C^5 at |x| = R, shaped like a Gaussian of
//   standard deviation R / sqrt 12),
// once with a narrow core radius and once with a wide envelope radius 4x larger ("tubes").
//
// Density: rho(x) = 1 + sum over tubes and chords of  a * W(x - m_k) |dc_k| / I0,
//   where I0 = (2048/3003) R is the line integral of W through its centre; on a straight spine the
//   tube profile is a * (1 - r^2/R^2)^(13/2) at distance r, so the spine holds 1 + a_core + a_env
//   (a_core 100..1000, a_env = a_core / 20; R_core 0.006..0.012, R_env = 4 R_core).
// Magnetic field: B = B0 + sum_m b_m cos(2 pi k_m . x + phi_m) + curl A,
//   A(x) = sum over tubes and chords of  beta * W(x - m_k) dc_k,
//   curl A = sum of beta * grad W(x - m_k) x dc_k = sum of -12 beta / R^2 * t^5 (x - m_k) x dc_k,
//   with t = 1 - |x - m_k|^2 / R^2. B0 = (1, 0, 0) is the mean field, the six modes (integer
//   wave vectors k_m, |b_m| = 0.2, b_m perpendicular to k_m) bend it on large scales, and curl A
//   wraps it azimuthally around each spine like the field of a smoothed line current.
//   Divergence-free analytically, term by term: div(f(|x - m|) (x - m) x c) = 0 for constant c,
//   and div(b cos(k . x)) = -(b . k) sin(k . x) = 0. Every term is C^4 (t^5 vanishes with four
//   derivatives at |x - m| = R). beta is set so a straight spine's peak wrap field is the
//   filament's coreWrap / envelopeWrap (peak at r = R / sqrt 12).
//
// Refinement: priority = (estimate of the max density in the block) * cell width, so a level
// halving the cell width resolves twice the density of the next coarser one.
//
// Evaluation at a point and over a block use the same kernels in the same order, so they agree
// bit for bit.

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "block_refiner.hpp"
#include "box.hpp"
#include "filament.hpp"

namespace amrstream::synth {

struct CloudSample {
  double density = 0.0;
  glm::dvec3 magneticField{0.0};
};

struct MagneticMode {  // amplitude * cos(2 pi wavevector . x + phase), amplitude . wavevector = 0
  glm::dvec3 amplitude{0.0};
  glm::dvec3 wavevector{0.0};
  double phase = 0.0;
};

class CloudField {
 public:
  static constexpr double kBackgroundDensity = 1.0;

  // One chord of one tube; the density and field terms of the header formula.
  struct Kernel {
    glm::dvec3 centre{0.0};
    glm::dvec3 wrap{0.0};  // -12 beta / R^2 * dc_k
    double inverseRadius2 = 0.0;
    double densityWeight = 0.0;  // a |dc_k| / I0
  };

  explicit CloudField(std::uint64_t seed);

  const std::vector<Filament>& filaments() const { return filaments_; }
  glm::dvec3 meanField() const { return meanField_; }
  const std::vector<MagneticMode>& modes() const { return modes_; }
  const std::vector<Kernel>& kernels() const { return kernels_; }  // every tube's, tube by tube

  CloudSample sample(glm::dvec3 p) const;
  double density(glm::dvec3 p) const { return sample(p).density; }
  glm::dvec3 magneticField(glm::dvec3 p) const { return sample(p).magneticField; }

  // An estimate of the largest density in the box, cheap enough to call for every block: the
  // background plus the largest over filaments of its straight-spine core + envelope profiles at
  // the box's distance from its spine. Filaments are not summed where they cross, so a coarse
  // block where several meet is not taken for a denser one.
  double peakDensityEstimate(const BlockBox& box) const;
  double refinementPriority(const BlockBox& box) const {
    return peakDensityEstimate(box) * box.cellWidth;
  }

  // values = dens, magx, magy, magz at the block's cell centres (a BlockSampler).
  void sampleBlock(const BlockBox& box, std::span<const glm::dvec3> centres,
                   std::span<float* const> values) const;

 private:
  struct Group {  // consecutive kernels of one tube, culled together
    Box centres;
    std::uint32_t first = 0;
    std::uint32_t count = 0;
  };
  struct Tube {
    std::uint32_t filament = 0;
    Box centres;
    std::uint32_t firstGroup = 0;
    std::uint32_t groupCount = 0;
    double radius = 0.0;
    double spacing = 0.0;  // longest chord
    double density = 0.0;  // a
  };

  void addTube(std::uint32_t filament, double radius, double density, double wrap);
  std::vector<std::uint32_t> kernelsNear(const Box& box) const;
  CloudSample evaluate(glm::dvec3 p, std::span<const std::uint32_t> kernels) const;

  std::vector<Filament> filaments_;
  glm::dvec3 meanField_{1.0, 0.0, 0.0};
  std::vector<MagneticMode> modes_;
  std::vector<Kernel> kernels_;
  std::vector<Group> groups_;
  std::vector<Tube> tubes_;
};

}  // namespace amrstream::synth
