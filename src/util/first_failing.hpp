#pragma once
// The lowest index whose check fails, found on all cores: input checks over tens of millions of
// cells or values must name the first bad one, as a serial loop would, without its cost.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstddef>

namespace amrstream {

// Lowest index in [0, n) for which `bad(state, i)` holds, or n. Runs in parallel; each range
// of indices has a `State` of its own, made by default and seeing the range's indices in order.
template <typename State, typename Predicate>
std::size_t firstFailingWith(std::size_t n, Predicate bad) {
  std::atomic<std::size_t> first{n};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const auto& range) {
    State state{};
    for (std::size_t i = range.begin(); i != range.end() && i < first.load(); ++i) {
      if (bad(state, i)) {
        std::size_t seen = first.load();
        while (i < seen && !first.compare_exchange_weak(seen, i)) {
        }
        return;
      }
    }
  });
  return first.load();
}

// Lowest index in [0, n) for which `bad(i)` holds, or n. Runs in parallel.
template <typename Predicate>
std::size_t firstFailing(std::size_t n, Predicate bad) {
  struct None {};
  return firstFailingWith<None>(n, [&](None&, std::size_t i) { return bad(i); });
}

}  // namespace amrstream
