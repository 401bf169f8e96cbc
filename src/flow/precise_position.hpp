#pragma once
// A physical position finer than float32 resolves (deep AMR hierarchies) kept as two floats: the
// position rounded to float ("high"), and what that rounding left out, rounded to float ("low").
// Their sum in double holds about 48 bits of the exact position.

#include <glm/glm.hpp>

namespace amrstream::flow {

struct SplitPosition {
  glm::vec3 high, low;
};

// vec3(exact), read back through a volatile: GCC 12 at -O2 and -O3, once it has vectorised both
// conversions, may fold dvec3(vec3(exact)) back to `exact` (seen in tests/output's precise tests:
// every low part came out 0).
inline glm::vec3 roundedToFloat(glm::dvec3 exact) {
  const volatile glm::vec3::value_type rounded[3] = {float(exact.x), float(exact.y),
                                                     float(exact.z)};
  return {rounded[0], rounded[1], rounded[2]};
}

inline SplitPosition splitPosition(glm::dvec3 exact) {
  const glm::vec3 high = roundedToFloat(exact);
  return {high, glm::vec3(exact - glm::dvec3(high))};
}

inline glm::dvec3 joinPosition(glm::vec3 high, glm::vec3 low) {
  return glm::dvec3(high) + glm::dvec3(low);
}

}  // namespace amrstream::flow
