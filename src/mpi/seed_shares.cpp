#include "seed_shares.hpp"

#include <algorithm>

#include "flow/morton_order.hpp"

namespace amrstream::mpi {

std::vector<std::vector<std::uint32_t>> mortonShares(std::span<const glm::dvec3> seeds, int parts) {
  std::vector<glm::vec3> points(seeds.size());
  std::ranges::transform(seeds, points.begin(), [](glm::dvec3 p) { return glm::vec3(p); });
  const std::vector<std::uint32_t> order = flow::mortonOrder(points);
  std::vector<std::vector<std::uint32_t>> shares(std::size_t(std::max(parts, 1)));
  const std::size_t n = order.size(), count = shares.size();
  const std::size_t block = std::max<std::size_t>(1, std::min(kSeedBlock, (n + count - 1) / count));
  for (std::size_t first = 0, k = 0; first < n; first += block, ++k) {
    const std::size_t last = std::min(n, first + block);
    shares[k % count].insert(shares[k % count].end(), order.begin() + std::ptrdiff_t(first),
                             order.begin() + std::ptrdiff_t(last));
  }
  for (std::vector<std::uint32_t>& share : shares) std::ranges::sort(share);
  return shares;
}

}  // namespace amrstream::mpi
