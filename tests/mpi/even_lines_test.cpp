// evenOutMoves(): after the moves every rank holds its share of the live lines (the floor of the
// mean, one more on the first ranks), only ranks above their share send, and no rank sends to
// itself; checked on hand-made counts and on random ones.

#include "mpi/even_lines.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

namespace amrstream::mpi {
namespace {

void expectEvenedOut(const std::vector<std::uint64_t>& live) {
  SCOPED_TRACE(::testing::PrintToString(live));
  const std::size_t ranks = live.size();
  const auto moves = evenOutMoves(live);
  ASSERT_EQ(moves.size(), ranks);
  const std::uint64_t total = std::accumulate(live.begin(), live.end(), std::uint64_t(0));
  for (std::size_t r = 0; r < ranks; ++r) {
    ASSERT_EQ(moves[r].size(), ranks);
    EXPECT_EQ(moves[r][r], 0u);
    std::uint64_t sent = 0, received = 0;
    for (std::size_t k = 0; k < ranks; ++k) {
      sent += moves[r][k];
      received += moves[k][r];
    }
    const std::uint64_t share = total / ranks + (r < total % ranks ? 1 : 0);
    EXPECT_EQ(live[r] - sent + received, share) << "rank " << r;
    if (live[r] <= share) EXPECT_EQ(sent, 0u) << "rank " << r;
    if (live[r] >= share) EXPECT_EQ(received, 0u) << "rank " << r;
  }
}

TEST(EvenOutMoves, GiveEveryRankItsShare) {
  expectEvenedOut({0});
  expectEvenedOut({5});
  expectEvenedOut({0, 0, 0});
  expectEvenedOut({10, 0, 5});
  expectEvenedOut({7, 7, 0, 1});
  expectEvenedOut({1, 0});
  expectEvenedOut({0, 1});
  expectEvenedOut({3, 3, 3});
  const auto moves = evenOutMoves(std::vector<std::uint64_t>{7, 7, 0, 1});
  EXPECT_EQ(moves[0][2], 3u);  // rank 2 first takes what rank 0 has over its 4
  EXPECT_EQ(moves[1][2], 1u);
  EXPECT_EQ(moves[1][3], 2u);
}

TEST(EvenOutMoves, RandomCounts) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<std::uint64_t> live(1 + rng() % 9);
    for (std::uint64_t& n : live) n = rng() % (trial % 2 == 0 ? 5 : 100000);
    expectEvenedOut(live);
  }
}

}  // namespace
}  // namespace amrstream::mpi
