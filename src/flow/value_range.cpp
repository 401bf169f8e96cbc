#include "value_range.hpp"

#include <fmt/format.h>

#include <cmath>

#include "util/input_error.hpp"

namespace amrstream::flow {

void checkChannelRange(std::span<const float> values, const std::string& source,
                       const std::string& name, float bound, const char* role) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::abs(values[i]) <= bound) continue;
    throw InputError(source, fmt::format("{} '{}' is {:g} at cell {}; amrstream's float32 "
                                         "arithmetic needs |values| <= {:g} there: rescale the "
                                         "field",
                                         role, name, values[i], i, bound));
  }
}

}  // namespace amrstream::flow
