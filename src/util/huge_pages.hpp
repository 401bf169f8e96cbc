#pragma once
// Advice that a large block of fresh memory be backed by transparent huge pages: its first touch
// then faults 2 MiB at a time instead of 4 KiB (hundreds of thousands of page faults for the
// arrays of a large input, taken by whichever thread touches them first).

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>

namespace amrstream {

// The whole pages of [data, data + bytes); advice only: without THP, plain pages.
inline void adviseHugePages(void* data, std::size_t bytes) {
  constexpr std::uintptr_t kPage = 4096;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

// An empty vector sized to `count` elements whose pages fault in 2 MiB at a time as resize()
// zeroes them: a single thread's zeroing of a large array is then bound by memory, not faults.
template <typename Vector>
void resizeInHugePages(Vector& array, std::size_t count) {
  array.reserve(count);
  adviseHugePages(array.data(), count * sizeof(typename Vector::value_type));
  array.resize(count);
}

}  // namespace amrstream
