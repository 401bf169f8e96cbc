#include "volume_range.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace amrstream::render {

namespace {

constexpr std::size_t kMaxSamples = 1 << 20;

struct WeightedValue {
  float value;   // log10 of the scalar when logarithmic
  double space;  // finest cells the cell fills
};

// An evenly strided subset of the original bricks' cells, which is plenty for percentiles and
// keeps large volumes fast; non-finite values (and with `logarithmic` those <= 0) left out.
std::vector<WeightedValue> sampledCells(const flow::VectorVolume& volume,
                                        std::span<const float> values, bool logarithmic) {
  const std::size_t stride = std::max<std::size_t>(1, values.size() / kMaxSamples);
  std::vector<WeightedValue> kept;
  kept.reserve(values.size() / stride + 1);
  for (std::size_t b = 0; b < volume.originalBrickCount; ++b) {
    const shared::Brick& brick = volume.bricks[b];
    const std::size_t first = brick.valueOffset;
    const std::size_t end =
        std::min(values.size(), first + std::size_t(brick.size.x) * brick.size.y * brick.size.z);
    const double space = std::ldexp(1.0, 3 * brick.level);
    for (std::size_t slot = (first + stride - 1) / stride * stride; slot < end; slot += stride) {
      const float v = values[slot];
      if (!std::isfinite(v) || (logarithmic && v <= 0.0f)) continue;
      kept.push_back({logarithmic ? std::log10(v) : v, space});
    }
  }
  return kept;
}

float medianBySpace(std::vector<WeightedValue> cells) {
  std::sort(cells.begin(), cells.end(),
            [](const WeightedValue& a, const WeightedValue& b) { return a.value < b.value; });
  double total = 0.0;
  for (const WeightedValue& c : cells) total += c.space;
  double below = 0.0;
  for (const WeightedValue& c : cells) {
    below += c.space;
    if (below >= 0.5 * total) return c.value;
  }
  return cells.back().value;
}

float percentileByCells(const std::vector<WeightedValue>& cells, double fraction) {
  std::vector<float> values;
  values.reserve(cells.size());
  for (const WeightedValue& c : cells) values.push_back(c.value);
  const auto k = static_cast<std::ptrdiff_t>(fraction * double(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[std::size_t(k)];
}

}  // namespace

ValueRange defaultVolumeRange(const flow::VectorVolume& volume, std::span<const float> values,
                              bool logarithmic) {
  const std::vector<WeightedValue> cells = sampledCells(volume, values, logarithmic);
  if (cells.empty()) return {};
  const float lo = medianBySpace(cells), hi = percentileByCells(cells, 0.999);
  if (hi > lo) return {lo, hi};
  float largest = lo;
  for (const WeightedValue& c : cells) largest = std::max(largest, c.value);
  return {lo, largest > lo ? largest : lo + 1.0f};
}

float defaultVolumeOpacity(const flow::VectorVolume& volume, std::span<const float> values,
                           bool logarithmic, ValueRange range) {
  const std::vector<WeightedValue> cells = sampledCells(volume, values, logarithmic);
  const float width = range.max - range.min;
  if (cells.empty() || !(width > 0.0f)) return kFallbackOpacity;
  double space = 0.0, weighted = 0.0;
  for (const WeightedValue& c : cells) {
    const double x = std::clamp((c.value - range.min) / width, 0.0f, 1.0f);
    space += c.space;
    weighted += c.space * x * x;
  }
  const glm::dvec3 extent = glm::dvec3(volume.domain.upper - volume.domain.lower);
  const double depth = (weighted / space) * (extent.x + extent.y + extent.z) / 3.0;
  if (!(depth > 0.0)) return kFallbackOpacity;
  return float(1.0 / depth);
}

}  // namespace amrstream::render
