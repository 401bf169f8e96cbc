#pragma once
// Seeds shared among ranks: contiguous ranges of their Morton order (gpu/morton_order.hpp), so
// that each rank's seeds lie together in space and its GPU threads stay coherent.

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace amrstream::dist {

// The seed indices of each of `parts` ranges (sizes differing by at most one), each range's
// indices ascending. Deterministic: every rank computes the same split from the same seeds.
std::vector<std::vector<std::uint32_t>> mortonRanges(std::span<const glm::dvec3> seeds, int parts);

}  // namespace amrstream::dist
