#include "value_range.hpp"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>

#include "util/input_error.hpp"

namespace amrstream::flow {

void checkChannelRange(std::span<const float> values, const std::string& source,
                       const std::string& name, float bound, const char* role) {
  // The first value out of range, found in parallel.
  const std::size_t first = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, values.size()), values.size(),
      [&](const tbb::blocked_range<std::size_t>& range, std::size_t found) {
        for (std::size_t i = range.begin(); i != range.end() && i < found; ++i)
          if (!(std::abs(values[i]) <= bound)) return i;
        return found;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  for (std::size_t i = first; i < values.size(); ++i) {
    if (std::abs(values[i]) <= bound) continue;
    throw InputError(source, fmt::format("{} '{}' is {:g} at cell {}; amrstream's float32 "
                                         "arithmetic needs |values| <= {:g} there: rescale the "
                                         "field",
                                         role, name, values[i], i, bound));
  }
}

}  // namespace amrstream::flow
