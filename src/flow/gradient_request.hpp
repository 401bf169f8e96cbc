#pragma once
// The gradient forms of the vector request: grad(NAME), the gradient of the scalar channel NAME
// per physical length, and -grad(NAME), its negative (heat flux runs down -grad(T)).

#include <optional>
#include <string>

#include "vector_selection.hpp"

namespace amrstream::flow {

struct GradientRequest {
  std::string scalar;  // NAME
  float sign = 1.0f;   // -1 for -grad(NAME)
};

// The gradient a request names; nothing for a request of another form (three channels, empty).
// A request that starts as a gradient ("grad(", "-grad(") must be one: InputError naming
// {vector} for "grad(", "grad()" or "grad(T)x". NAME is everything between "grad(" and the last
// ')', so names with parentheses such as Y(H2) are taken whole.
std::optional<GradientRequest> parseGradientRequest(const std::string& request);

// The vector of a gradient: named "grad(NAME)" or "-grad(NAME)", its components "d(NAME)/dx",
// "d(NAME)/dy", "d(NAME)/dz" (with a leading '-' for the negative).
VectorChannels gradientVector(const GradientRequest& gradient);

}  // namespace amrstream::flow
