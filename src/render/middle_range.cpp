#include "middle_range.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace amrstream::render {

std::optional<ValueRange> middleRange(std::span<const shared::TubeSegment> segments, double low,
                                      double high) {
  const std::size_t stride = std::max<std::size_t>(1, segments.size() / kMiddleRangeSamples);
  std::vector<float> values;
  values.reserve(2 * (segments.size() / stride + 1));
  for (std::size_t i = 0; i < segments.size(); i += stride)
    for (const float v : {segments[i].valueA, segments[i].valueB})
      if (std::isfinite(v) && v != float(AMRSTREAM_OUTLINE_VALUE)) values.push_back(v);
  if (values.empty()) return std::nullopt;
  const auto quantile = [&](double fraction) {
    const auto k = static_cast<std::ptrdiff_t>(std::lround(fraction * double(values.size() - 1)));
    std::nth_element(values.begin(), values.begin() + k, values.end());
    return values[std::size_t(k)];
  };
  const ValueRange range{quantile(low), quantile(high)};
  if (!(range.min < range.max)) return std::nullopt;
  return range;
}

}  // namespace amrstream::render
