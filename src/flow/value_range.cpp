#include "value_range.hpp"

#include <fmt/format.h>

#include <cmath>

#include "amrstream/error.hpp"
#include "util/first_failing.hpp"

namespace amrstream::flow {

void checkChannelRange(std::span<const float> values, const std::string& source,
                       const std::string& name, float bound, const char* role) {
  const std::size_t i =
      firstFailing(values.size(), [&](std::size_t k) { return !(std::abs(values[k]) <= bound); });
  if (i < values.size())
    throw InputError(source, fmt::format("{} '{}' is {:g} at cell {}; amrstream's float32 "
                                         "arithmetic needs |values| <= {:g} there: rescale the "
                                         "field",
                                         role, name, values[i], i, bound));
}

}  // namespace amrstream::flow
