// mortonShares(): every seed in exactly one share; each share made of blocks of consecutive
// seeds of the Morton order, block k on rank k mod parts; counts within one block of each other;
// the same split every time.

#include "mpi/seed_shares.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "flow/morton_order.hpp"

namespace amrstream::mpi {
namespace {

std::vector<glm::dvec3> randomPoints(std::size_t n) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 3.0);
  std::vector<glm::dvec3> points(n);
  for (glm::dvec3& p : points) p = {u(rng), u(rng), u(rng)};
  return points;
}

TEST(MortonShares, DealBlocksOfTheMortonOrderRoundTheRanks) {
  for (const std::size_t n : {0u, 1u, 2u, 7u, 1000u, 3u * 4096u + 17u, 40000u})
    for (const int parts : {1, 2, 3, 8}) {
      SCOPED_TRACE(::testing::Message() << n << " seeds, " << parts << " parts");
      const std::vector<glm::dvec3> seeds = randomPoints(n);
      const auto shares = mortonShares(seeds, parts);
      ASSERT_EQ(shares.size(), std::size_t(parts));
      const std::vector<glm::vec3> floats(seeds.begin(), seeds.end());
      const std::vector<std::uint32_t> order = flow::mortonOrder(floats);
      const std::size_t block =
          std::max<std::size_t>(1, std::min(kSeedBlock, (n + parts - 1) / std::size_t(parts)));
      std::vector<std::vector<std::uint32_t>> expected(shares.size());
      for (std::size_t at = 0; at < n; ++at)
        expected[(at / block) % shares.size()].push_back(order[at]);
      std::size_t fewest = n, most = 0;
      for (std::size_t k = 0; k < shares.size(); ++k) {
        std::ranges::sort(expected[k]);
        EXPECT_EQ(shares[k], expected[k]);
        fewest = std::min(fewest, shares[k].size());
        most = std::max(most, shares[k].size());
      }
      EXPECT_LE(most - std::min(fewest, most), block);
      EXPECT_EQ(mortonShares(seeds, parts), shares);
    }
}

}  // namespace
}  // namespace amrstream::mpi
