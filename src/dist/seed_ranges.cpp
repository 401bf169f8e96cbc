#include "seed_ranges.hpp"

#include <algorithm>

#include "gpu/morton_order.hpp"

namespace amrstream::dist {

std::vector<std::vector<std::uint32_t>> mortonRanges(std::span<const glm::dvec3> seeds,
                                                     int parts) {
  std::vector<glm::vec3> points(seeds.size());
  std::ranges::transform(seeds, points.begin(), [](glm::dvec3 p) { return glm::vec3(p); });
  const std::vector<std::uint32_t> order = gpu::mortonOrder(points);
  std::vector<std::vector<std::uint32_t>> ranges(std::size_t(std::max(parts, 1)));
  const std::size_t n = order.size(), count = ranges.size();
  for (std::size_t k = 0; k < count; ++k) {
    const auto first = order.begin() + std::ptrdiff_t(k * n / count);
    const auto last = order.begin() + std::ptrdiff_t((k + 1) * n / count);
    ranges[k].assign(first, last);
    std::ranges::sort(ranges[k]);
  }
  return ranges;
}

}  // namespace amrstream::dist
