#pragma once
// Copies bytes on all cores, a megabyte a task: one core writes pinned (host-visible) memory at a
// few GB/s.

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <span>

namespace amrstream {

// `to` holds at least from.size() bytes.
inline void copyParallel(std::span<const std::byte> from, std::span<std::byte> to) {
  constexpr std::size_t kGrain = std::size_t(1) << 20;
  tbb::parallel_for(std::size_t(0), (from.size() + kGrain - 1) / kGrain, [&](std::size_t part) {
    const std::size_t first = part * kGrain, n = std::min(kGrain, from.size() - first);
    std::memcpy(to.data() + first, from.data() + first, n);
  });
}

}  // namespace amrstream
