#pragma once
// Column<T>: a std::vector for trace points, which are written once, right after the storage for
// them is made, often hundreds of megabytes at a time.
// - resize() leaves new elements of trivial types uninitialised: a zero fill first would double
//   the memory traffic of collecting them.
// - Large columns ask the kernel for transparent huge pages: first touching fresh memory 4 KiB at
//   a time (a page fault each) is what bounds copying points out of the device.

#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace amrstream::flow {

namespace column_memory {

inline constexpr std::size_t kHugePage = std::size_t(2) << 20;
inline constexpr std::size_t kHugeFrom = 4 * kHugePage;

inline std::size_t hugeBytes(std::size_t bytes) {
  return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

inline void* allocate(std::size_t bytes) {
  if (bytes < kHugeFrom) return ::operator new(bytes);
  void* p = std::aligned_alloc(kHugePage, hugeBytes(bytes));
  if (!p) throw std::bad_alloc();
  ::madvise(p, hugeBytes(bytes), MADV_HUGEPAGE);  // advice only: without THP, plain pages
  return p;
}

inline void deallocate(void* p, std::size_t bytes) noexcept {
  if (bytes < kHugeFrom)
    ::operator delete(p);
  else
    std::free(p);
}

}  // namespace column_memory

template <typename T>
struct ColumnAllocator {
  using value_type = T;
  template <typename U>
  struct rebind {
    using other = ColumnAllocator<U>;
  };
  ColumnAllocator() = default;
  template <typename U>
  ColumnAllocator(const ColumnAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(column_memory::allocate(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { column_memory::deallocate(p, n * sizeof(T)); }

  // Default-initialises (for trivial types: leaves alone) where std::allocator value-initialises.
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <typename U>
  bool operator==(const ColumnAllocator<U>&) const noexcept {
    return true;
  }
};

template <typename T>
using Column = std::vector<T, ColumnAllocator<T>>;

}  // namespace amrstream::flow
