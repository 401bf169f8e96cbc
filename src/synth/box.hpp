#pragma once
// Axis-aligned boxes in physical coordinates, for culling filament kernels against blocks.

#include <glm/glm.hpp>
#include <limits>

namespace amrstream::synth {

struct Box {
  glm::dvec3 lower{std::numeric_limits<double>::max()};  // empty until a point is included
  glm::dvec3 upper{std::numeric_limits<double>::lowest()};

  void include(glm::dvec3 p) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
};

inline double distance2(const Box& box, glm::dvec3 p) {
  const glm::dvec3 d = glm::max(glm::max(box.lower - p, p - box.upper), glm::dvec3(0.0));
  return glm::dot(d, d);
}

inline double distance2(const Box& a, const Box& b) {
  const glm::dvec3 d = glm::max(glm::max(a.lower - b.upper, b.lower - a.upper), glm::dvec3(0.0));
  return glm::dot(d, d);
}

}  // namespace amrstream::synth
