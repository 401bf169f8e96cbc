#pragma once
// Seeds shared among ranks: the Morton order of the seeds (gpu/morton_order.hpp) cut into blocks
// of neighbouring seeds, dealt to the ranks in turn. Within a block the seeds lie together, so a
// rank's GPU threads stay coherent; dealing many blocks round the ranks gives every rank seeds
// from all over the domain, so that regions where traces run long or end early weigh on every
// rank alike (docs/distributed.md, "`--distribute seeds`").

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace amrstream::mpi {

// Seeds per block at most: a few GPU subgroups' worth and more, far fewer than a GPU's threads.
inline constexpr std::size_t kSeedBlock = 4096;

// The seed indices of each of `parts` ranks, each ascending: blocks of min(kSeedBlock,
// ceil(n / parts)) consecutive seeds of the Morton order, block k to rank k mod parts. Counts
// differ by at most one block. Deterministic: every rank computes the same split.
std::vector<std::vector<std::uint32_t>> mortonShares(std::span<const glm::dvec3> seeds, int parts);

}  // namespace amrstream::mpi
