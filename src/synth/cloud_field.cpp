#include "cloud_field.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "split_mix.hpp"

namespace amrstream::synth {

namespace {

constexpr int kChordsPerRadius = 4;
constexpr std::uint32_t kGroupSize = 16;  // kernels per culling group
constexpr int kModeCount = 6;
constexpr double kModeAmplitude = 0.2;

// Line integral of W = (1 - q^2)^6 through its centre, over R: int (1 - u^2)^6 du on [-1, 1].
constexpr double kKernelLineIntegral = 2048.0 / 3003.0;
// A straight spine's A = beta I(r) with I(r) = (2048/3003) (R^2 - r^2)^(13/2) / R^12, so
// B_phi = -beta I'(r) = beta (2048/3003) 13 r (R^2 - r^2)^(11/2) / R^12,
// largest at r = R / sqrt 12.
const double kWrapPeak = 2048.0 / 3003.0 * 13.0 * std::pow(11.0 / 12.0, 5.5) / std::sqrt(12.0);

glm::dvec3 perpendicularTo(glm::dvec3 axis, glm::dvec3 v) {
  return glm::normalize(v - glm::dot(v, axis) * axis);
}

Filament randomFilament(SplitMix64& rng, glm::dvec3 hub) {
  const glm::dvec3 middle = hub + rng.inBall(0.2);
  const glm::dvec3 direction = rng.unitVector();
  const double length = rng.uniform(0.7, 1.2);
  const glm::dvec3 bend1 =
      perpendicularTo(direction, rng.unitVector()) * (rng.uniform(0.0, 0.2) * length);
  const glm::dvec3 bend2 =
      perpendicularTo(direction, rng.unitVector()) * (rng.uniform(0.0, 0.2) * length);
  Filament f;
  f.controls = {middle - direction * (length / 2), middle - direction * (length / 6) + bend1,
                middle + direction * (length / 6) + bend2, middle + direction * (length / 2)};
  f.coreRadius = rng.logUniform(0.006, 0.012);
  f.envelopeRadius = 4.0 * f.coreRadius;
  f.coreDensity = rng.logUniform(100.0, 1000.0);
  f.envelopeDensity = f.coreDensity / 20.0;
  const double sign = rng.sign();
  f.coreWrap = sign * rng.uniform(0.5, 1.5);
  f.envelopeWrap = sign * rng.uniform(0.3, 1.0);
  return f;
}

MagneticMode randomMode(SplitMix64& rng) {
  MagneticMode mode;
  do {
    mode.wavevector = glm::dvec3(rng.below(7) - 3, rng.below(7) - 3, rng.below(7) - 3);
  } while (mode.wavevector == glm::dvec3(0.0));
  const glm::dvec3 k = glm::normalize(mode.wavevector);
  mode.amplitude = kModeAmplitude * perpendicularTo(k, rng.unitVector());
  mode.phase = rng.uniform(0.0, 2.0 * std::numbers::pi);
  return mode;
}

}  // namespace

CloudField::CloudField(std::uint64_t seed) {
  SplitMix64 rng(seed);
  const glm::dvec3 hub(rng.uniform(0.4, 0.6), rng.uniform(0.4, 0.6), rng.uniform(0.4, 0.6));
  const int count = 4 + rng.below(5);
  for (int i = 0; i < count; ++i) filaments_.push_back(randomFilament(rng, hub));
  for (int i = 0; i < kModeCount; ++i) modes_.push_back(randomMode(rng));
  for (std::uint32_t i = 0; i < filaments_.size(); ++i) {
    const Filament& f = filaments_[i];
    addTube(i, f.coreRadius, f.coreDensity, f.coreWrap);
    addTube(i, f.envelopeRadius, f.envelopeDensity, f.envelopeWrap);
  }
}

void CloudField::addTube(std::uint32_t filamentIndex, double radius, double density, double wrap) {
  const Filament& filament = filaments_[filamentIndex];
  const auto& c = filament.controls;
  const double polygon =
      glm::length(c[1] - c[0]) + glm::length(c[2] - c[1]) + glm::length(c[3] - c[2]);
  // The arc is no longer than its control polygon, so every chord is at most R / 4.
  const std::uint32_t chords =
      std::max(1u, std::uint32_t(std::ceil(kChordsPerRadius * polygon / radius)));
  const double beta = wrap / kWrapPeak;
  const double lineIntegral = kKernelLineIntegral * radius;

  Tube tube;
  tube.filament = filamentIndex;
  tube.firstGroup = std::uint32_t(groups_.size());
  tube.radius = radius;
  tube.density = density;
  glm::dvec3 previous = filament.pointAt(0.0);
  for (std::uint32_t k = 0; k < chords; ++k) {
    const glm::dvec3 next = filament.pointAt(double(k + 1) / chords);
    const glm::dvec3 chord = next - previous;
    Kernel kernel;
    kernel.centre = 0.5 * (previous + next);
    kernel.wrap = (-12.0 * beta / (radius * radius)) * chord;
    kernel.inverseRadius2 = 1.0 / (radius * radius);
    kernel.densityWeight = density * glm::length(chord) / lineIntegral;
    if (k % kGroupSize == 0) groups_.push_back({Box{}, std::uint32_t(kernels_.size()), 0});
    groups_.back().centres.include(kernel.centre);
    ++groups_.back().count;
    tube.centres.include(kernel.centre);
    tube.spacing = std::max(tube.spacing, glm::length(chord));
    kernels_.push_back(kernel);
    previous = next;
  }
  tube.groupCount = std::uint32_t(groups_.size()) - tube.firstGroup;
  tubes_.push_back(tube);
}

std::vector<std::uint32_t> CloudField::kernelsNear(const Box& box) const {
  std::vector<std::uint32_t> near;
  for (const Tube& tube : tubes_) {
    // A little above R^2, so that rounding never drops a kernel that evaluate() would count.
    const double reach2 = tube.radius * tube.radius * (1.0 + 1e-9);
    if (distance2(box, tube.centres) >= reach2) continue;
    for (std::uint32_t g = tube.firstGroup; g < tube.firstGroup + tube.groupCount; ++g) {
      const Group& group = groups_[g];
      if (distance2(box, group.centres) >= reach2) continue;
      for (std::uint32_t k = group.first; k < group.first + group.count; ++k)
        if (distance2(box, kernels_[k].centre) < reach2) near.push_back(k);
    }
  }
  return near;
}

CloudSample CloudField::evaluate(glm::dvec3 p, std::span<const std::uint32_t> kernels) const {
  double density = 0.0;
  glm::dvec3 field(0.0);
  for (std::uint32_t k : kernels) {
    const Kernel& kernel = kernels_[k];
    const glm::dvec3 d = p - kernel.centre;
    const double t = 1.0 - glm::dot(d, d) * kernel.inverseRadius2;
    if (t <= 0.0) continue;
    const double t2 = t * t;
    const double t5 = t2 * t2 * t;
    density += kernel.densityWeight * (t5 * t);
    field += t5 * glm::cross(d, kernel.wrap);
  }
  field += meanField_;
  for (const MagneticMode& mode : modes_)
    field += mode.amplitude *
             std::cos(2.0 * std::numbers::pi * glm::dot(mode.wavevector, p) + mode.phase);
  return {kBackgroundDensity + density, field};
}

CloudSample CloudField::sample(glm::dvec3 p) const { return evaluate(p, kernelsNear(Box{p, p})); }

double CloudField::peakDensityEstimate(const BlockBox& block) const {
  const Box box{block.lower, block.upper};
  std::vector<double> perFilament(filaments_.size(), 0.0);
  for (const Tube& tube : tubes_) {
    // The spine passes within half a chord of some chord midpoint.
    const double reach = tube.radius + 0.5 * tube.spacing;
    if (distance2(box, tube.centres) >= reach * reach) continue;
    double nearest2 = reach * reach;
    for (std::uint32_t g = tube.firstGroup; g < tube.firstGroup + tube.groupCount; ++g) {
      const Group& group = groups_[g];
      if (distance2(box, group.centres) >= nearest2) continue;
      for (std::uint32_t k = group.first; k < group.first + group.count; ++k)
        nearest2 = std::min(nearest2, distance2(box, kernels_[k].centre));
    }
    const double r = std::max(0.0, std::sqrt(nearest2) - 0.5 * tube.spacing);
    if (r < tube.radius)
      perFilament[tube.filament] +=
          tube.density * std::pow(1.0 - r * r / (tube.radius * tube.radius), 6.5);
  }
  return kBackgroundDensity + *std::max_element(perFilament.begin(), perFilament.end());
}

void CloudField::sampleBlock(const BlockBox& block, std::span<const glm::dvec3> centres,
                             std::span<float* const> values) const {
  const std::vector<std::uint32_t> near = kernelsNear(Box{block.lower, block.upper});
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const CloudSample s = evaluate(centres[i], near);
    values[0][i] = float(s.density);
    values[1][i] = float(s.magneticField.x);
    values[2][i] = float(s.magneticField.y);
    values[3][i] = float(s.magneticField.z);
  }
}

}  // namespace amrstream::synth
