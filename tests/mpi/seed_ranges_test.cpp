// mortonRanges(): every seed in exactly one range, sizes within one of each other, each range a
// contiguous run of the Morton order (so its seeds lie together), the same split every time.

#include "dist/seed_ranges.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "gpu/morton_order.hpp"

namespace amrstream::dist {
namespace {

std::vector<glm::dvec3> randomPoints(std::size_t n) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 3.0);
  std::vector<glm::dvec3> points(n);
  for (glm::dvec3& p : points) p = {u(rng), u(rng), u(rng)};
  return points;
}

TEST(MortonRanges, PartitionTheSeedsIntoContiguousRunsOfTheMortonOrder) {
  for (const std::size_t n : {0u, 1u, 2u, 7u, 1000u})
    for (const int parts : {1, 2, 3, 8}) {
      SCOPED_TRACE(::testing::Message() << n << " seeds, " << parts << " parts");
      const std::vector<glm::dvec3> seeds = randomPoints(n);
      const auto ranges = mortonRanges(seeds, parts);
      ASSERT_EQ(ranges.size(), std::size_t(parts));
      std::vector<glm::vec3> floats(seeds.begin(), seeds.end());
      const std::vector<std::uint32_t> order = gpu::mortonOrder(floats);
      std::size_t at = 0, fewest = n, most = 0;
      for (const auto& range : ranges) {
        EXPECT_TRUE(std::ranges::is_sorted(range));
        std::vector<std::uint32_t> run(order.begin() + std::ptrdiff_t(at),
                                       order.begin() + std::ptrdiff_t(at + range.size()));
        std::ranges::sort(run);
        EXPECT_EQ(run, range);
        at += range.size();
        fewest = std::min(fewest, range.size());
        most = std::max(most, range.size());
      }
      EXPECT_EQ(at, n);
      EXPECT_LE(most - std::min(fewest, most), 1u);
      EXPECT_EQ(mortonRanges(seeds, parts), ranges);
    }
}

}  // namespace
}  // namespace amrstream::dist
