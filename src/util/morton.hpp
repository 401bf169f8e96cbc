#pragma once
// Morton (Z-order) keys: the bits of three coordinates interleaved, x lowest, so that points near
// each other in space tend to be near each other in key order.

#include <cstdint>
#include <glm/glm.hpp>

namespace amrstream {

// Interleaves the low 21 bits of x with two zero bits after each.
constexpr std::uint64_t mortonSpread(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffull;
  x = (x | x << 16) & 0x1f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

// The key of a point with coordinates below 2^21 on each axis (higher bits are dropped).
constexpr std::uint64_t mortonKey(glm::uvec3 p) {
  return mortonSpread(p.x) | mortonSpread(p.y) << 1 | mortonSpread(p.z) << 2;
}

static_assert(mortonKey({1, 0, 0}) == 1 && mortonKey({0, 1, 0}) == 2 && mortonKey({0, 0, 1}) == 4);
static_assert(mortonKey({1023, 1023, 1023}) == (1u << 30) - 1);

}  // namespace amrstream
