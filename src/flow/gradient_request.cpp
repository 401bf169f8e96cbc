#include "gradient_request.hpp"

#include <fmt/format.h>

#include <string_view>

#include "amrstream/error.hpp"

namespace amrstream::flow {

std::optional<GradientRequest> parseGradientRequest(const std::string& request) {
  const std::string_view text(request);
  GradientRequest gradient;
  std::string_view rest;
  if (text.starts_with("grad(")) {
    rest = text.substr(5);
  } else if (text.starts_with("-grad(")) {
    rest = text.substr(6);
    gradient.sign = -1.0f;
  } else {
    return std::nullopt;
  }
  if (rest.size() < 2 || !rest.ends_with(')'))
    throw settingError("vector", fmt::format("'{}' is not grad(NAME) or -grad(NAME) with NAME a "
                                             "scalar channel (nor three channels a,b,c)",
                                             request));
  gradient.scalar = std::string(rest.substr(0, rest.size() - 1));
  return gradient;
}

VectorChannels gradientVector(const GradientRequest& gradient) {
  const std::string sign = gradient.sign < 0.0f ? "-" : "";
  VectorChannels vector;
  for (int axis = 0; axis < 3; ++axis)
    vector.channels[axis] = fmt::format("{}d({})/d{}", sign, gradient.scalar, "xyz"[axis]);
  vector.name = fmt::format("{}grad({})", sign, gradient.scalar);
  vector.gradientOf = gradient.scalar;
  vector.gradientSign = gradient.sign;
  return vector;
}

}  // namespace amrstream::flow
