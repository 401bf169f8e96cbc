#pragma once
// Deterministic random numbers for the generators: SplitMix64 (Steele, Lea, Flood 2014) and
// distributions written out here, so a seed gives the same dataset with any standard library
// (std::uniform_real_distribution is implementation-defined).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <numbers>

namespace amrstream::synth {

class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }

  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  double logUniform(double low, double high) {
    return low * std::exp(std::log(high / low) * uniform());
  }
  int below(int n) { return int(next() % std::uint64_t(n)); }  // [0, n); bias is negligible
  double sign() { return (next() >> 63) ? 1.0 : -1.0; }

  glm::dvec3 unitVector() {  // uniform on the sphere (Archimedes: z uniform in [-1, 1])
    const double z = uniform(-1.0, 1.0);
    const double phi = uniform(0.0, 2.0 * std::numbers::pi);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
  }

  glm::dvec3 inBall(double radius) {  // uniform in the ball
    return unitVector() * (radius * std::cbrt(uniform()));
  }

 private:
  std::uint64_t state_;
};

}  // namespace amrstream::synth
