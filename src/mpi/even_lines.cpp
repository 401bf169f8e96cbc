#include "even_lines.hpp"

#include <algorithm>
#include <cstring>

namespace amrstream::mpi {

std::vector<std::vector<std::uint64_t>> evenOutMoves(std::span<const std::uint64_t> live) {
  const std::size_t ranks = live.size();
  std::vector<std::vector<std::uint64_t>> moves(ranks, std::vector<std::uint64_t>(ranks, 0));
  std::uint64_t total = 0;
  for (const std::uint64_t n : live) total += n;
  const auto share = [&](std::size_t r) { return total / ranks + (r < total % ranks ? 1 : 0); };
  std::size_t to = 0;
  std::uint64_t taken = 0;  // lines rank `to` has received so far
  for (std::size_t from = 0; from < ranks; ++from) {
    std::uint64_t surplus = live[from] > share(from) ? live[from] - share(from) : 0;
    while (surplus > 0) {
      while (live[to] + taken >= share(to)) {
        ++to;
        taken = 0;
      }
      const std::uint64_t n = std::min(surplus, share(to) - live[to] - taken);
      moves[from][to] += n;
      taken += n;
      surplus -= n;
    }
  }
  return moves;
}

LineRouting evenOutLines(const MpiWorld& world) {
  return [&world](std::vector<shared::LineState>& live,
                  std::vector<std::vector<shared::LineState>>& outgoing) {
    const std::uint64_t mine = live.size();
    const std::vector<std::byte> bytes = world.gatherToAll(std::as_bytes(std::span(&mine, 1)));
    std::vector<std::uint64_t> counts(std::size_t(world.size()));
    std::memcpy(counts.data(), bytes.data(), counts.size() * sizeof(std::uint64_t));
    const std::vector<std::uint64_t> sends = evenOutMoves(counts)[std::size_t(world.rank())];
    std::size_t end = live.size();
    for (std::size_t to = 0; to < sends.size(); ++to) {
      auto first = live.begin() + std::ptrdiff_t(end - sends[to]);
      outgoing[to].assign(first, live.begin() + std::ptrdiff_t(end));
      end -= sends[to];
    }
    live.resize(end);
  };
}

}  // namespace amrstream::mpi
