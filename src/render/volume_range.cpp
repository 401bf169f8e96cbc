#include "volume_range.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace amrstream::render {

namespace {

constexpr std::size_t kMaxSamples = 1 << 20;

float percentile(std::vector<float>& values, double fraction) {
  const auto k = static_cast<std::ptrdiff_t>(fraction * double(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

}  // namespace

ValueRange defaultVolumeRange(std::span<const float> values, bool logarithmic) {
  // An evenly strided subset is plenty for percentiles and keeps large volumes fast.
  const std::size_t stride = std::max<std::size_t>(1, values.size() / kMaxSamples);
  std::vector<float> kept;
  kept.reserve(values.size() / stride + 1);
  for (std::size_t i = 0; i < values.size(); i += stride) {
    const float v = values[i];
    if (!std::isfinite(v) || (logarithmic && v <= 0.0f)) continue;
    kept.push_back(logarithmic ? std::log10(v) : v);
  }
  if (kept.empty()) return {};
  const float lo = percentile(kept, 0.5), hi = percentile(kept, 0.999);
  if (hi > lo) return {lo, hi};
  return {lo, lo + 1.0f};
}

}  // namespace amrstream::render
