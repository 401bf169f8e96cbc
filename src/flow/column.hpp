#pragma once
// Column<T>: a std::vector whose resize() leaves new elements of trivial types uninitialised.
// Trace points are written once, right after the storage for them is made, often hundreds of
// megabytes at a time: a zero fill first would double the memory traffic of collecting them.

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace amrstream::flow {

template <typename T>
struct DefaultInitAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <typename U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

  // Default-initialises (for trivial types: leaves alone) where std::allocator value-initialises.
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <typename T>
using Column = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace amrstream::flow
