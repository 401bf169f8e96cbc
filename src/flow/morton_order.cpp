#include "morton_order.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include <limits>
#include <utility>

#include "util/morton.hpp"

namespace amrstream::flow {

std::vector<std::uint32_t> mortonOrder(std::span<const glm::vec3> points) {
  using Box = std::pair<glm::vec3, glm::vec3>;
  const Box empty{glm::vec3(std::numeric_limits<float>::max()),
                  glm::vec3(-std::numeric_limits<float>::max())};
  const auto [lo, hi] = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, points.size()), empty,
      [&](const tbb::blocked_range<std::size_t>& range, Box box) {
        for (std::size_t i = range.begin(); i != range.end(); ++i)
          box = {glm::min(box.first, points[i]), glm::max(box.second, points[i])};
        return box;
      },
      [](const Box& a, const Box& b) {
        return Box{glm::min(a.first, b.first), glm::max(a.second, b.second)};
      });
  const glm::vec3 scale = 1023.0f / glm::max(hi - lo, glm::vec3(1e-20f));
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(points.size());
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
    const glm::uvec3 q(glm::clamp((points[i] - lo) * scale, glm::vec3(0.0f), glm::vec3(1023.0f)));
    keyed[i] = {mortonKey(q), static_cast<std::uint32_t>(i)};
  });
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(points.size());
  tbb::parallel_for(std::size_t(0), keyed.size(),
                    [&](std::size_t k) { order[k] = keyed[k].second; });
  return order;
}

}  // namespace amrstream::flow
