#pragma once
// The live lines re-split among the ranks between rounds when tracing over seeds
// (--rebalance-steps): every rank holds the whole volume, so a line may go on on any rank. The
// ranks with more live lines than their share hand the surplus to those with fewer, so that a
// rank whose lines ended early takes over lines from the others instead of waiting for them.

#include <cstdint>
#include <span>
#include <vector>

#include "amrstream/mpi_world.hpp"
#include "data_rounds.hpp"

namespace amrstream::mpi {

// moves[from][to]: the lines rank `from` hands to rank `to` so that every rank holds its share of
// the sum of `live` (the floor of the mean, one more on the first ranks for the remainder). Ranks
// above their share send, in rank order, to ranks below it, in rank order.
std::vector<std::vector<std::uint64_t>> evenOutMoves(std::span<const std::uint64_t> live);

// A LineRouting that evens out the ranks' live lines (collective: the ranks share their counts).
// A rank hands on its last lines, which lie together in its order.
LineRouting evenOutLines(const MpiWorld& world);

}  // namespace amrstream::mpi
