#pragma once
// Advice that a large block of fresh memory be backed by transparent huge pages: its first touch
// then faults 2 MiB at a time instead of 4 KiB (hundreds of thousands of page faults for the
// arrays of a large input, taken by whichever thread touches them first).

#include <sys/mman.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace amrstream {

// The whole pages of [data, data + bytes); advice only: without THP, plain pages.
inline void adviseHugePages(void* data, std::size_t bytes) {
  constexpr std::uintptr_t kPage = 4096;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

// Writes zeros over [data, data + bytes) on all cores, 2 MiB a task: the kernel zeroes each fresh
// page at its first touch, which takes several times as long as the writes that follow.
inline void zeroInParallel(std::byte* data, std::size_t bytes) {
  constexpr std::size_t kGrain = std::size_t(1) << 21;
  tbb::parallel_for(std::size_t(0), (bytes + kGrain - 1) / kGrain, [&](std::size_t part) {
    const std::size_t first = part * kGrain;
    std::memset(data + first, 0, std::min(kGrain, bytes - first));
  });
}

// An empty vector of trivial elements sized to `count` zeroed elements, its pages faulted in 2 MiB
// at a time and on all cores before resize() zeroes them again on this one, now without faults.
template <typename Vector>
void resizeInHugePages(Vector& array, std::size_t count) {
  using Value = typename Vector::value_type;
  static_assert(std::is_trivially_default_constructible_v<Value> &&
                std::is_trivially_copyable_v<Value>);
  array.reserve(count);
  const std::size_t kept = std::min(array.size(), count);
  adviseHugePages(array.data(), count * sizeof(Value));
  zeroInParallel(reinterpret_cast<std::byte*>(array.data() + kept), (count - kept) * sizeof(Value));
  array.resize(count);
}

}  // namespace amrstream
