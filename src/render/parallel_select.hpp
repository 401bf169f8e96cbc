#pragma once
// std::nth_element on all cores, for the large nodes of a BVH build.

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <span>
#include <vector>

namespace amrstream::render {

// Arranges `items` as std::nth_element(items.begin(), items.begin() + k, items.end(), less)
// would: the k-th in `less`'s order at k, none after it less than it, none before it greater.
// Two keys that bracket the k-th of an even sample split the items into three classes, which a
// stable parallel scatter moves into place; only the middle class, a few per cent of the items,
// is then selected in one thread. When the sample misleads (the k-th falls outside the middle
// class) it falls back to std::nth_element. With a strict total order the result does not depend
// on the number of threads. `scratch` (as many items) is overwritten. k < items.size().
template <typename T, typename Less>
void parallelNthElement(std::span<T> items, std::size_t k, Less less, std::span<T> scratch) {
  constexpr std::size_t kSample = 4096, kMargin = 128, kBlock = std::size_t(1) << 14;
  const std::size_t n = items.size();
  if (n <= 2 * kBlock) {
    std::nth_element(items.begin(), items.begin() + std::ptrdiff_t(k), items.end(), less);
    return;
  }
  std::vector<T> sample(kSample);
  for (std::size_t i = 0; i < kSample; ++i) sample[i] = items[i * n / kSample];
  std::sort(sample.begin(), sample.end(), less);
  const std::size_t at = k * kSample / n;
  const T lo = sample[at > kMargin ? at - kMargin : 0];
  const T hi = sample[std::min(kSample - 1, at + kMargin)];
  const auto classOf = [&](const T& item) { return less(item, lo) ? 0 : less(hi, item) ? 2 : 1; };

  using Counts = std::array<std::size_t, 3>;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  const auto blockEnd = [&](std::size_t b) { return std::min(n, (b + 1) * kBlock); };
  std::vector<Counts> starts(blocks);
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    Counts c{};
    for (std::size_t i = b * kBlock; i < blockEnd(b); ++i) ++c[classOf(items[i])];
    starts[b] = c;
  });
  Counts total{};
  for (const Counts& c : starts)
    for (int j = 0; j < 3; ++j) total[j] += c[j];
  if (k < total[0] || k >= total[0] + total[1]) {
    std::nth_element(items.begin(), items.begin() + std::ptrdiff_t(k), items.end(), less);
    return;
  }
  Counts next{0, total[0], total[0] + total[1]};
  for (Counts& c : starts) {  // each block's counts become where its classes start
    const Counts count = c;
    c = next;
    for (int j = 0; j < 3; ++j) next[j] += count[j];
  }
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    Counts to = starts[b];
    for (std::size_t i = b * kBlock; i < blockEnd(b); ++i)
      scratch[to[classOf(items[i])]++] = items[i];
  });
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    std::copy(scratch.begin() + std::ptrdiff_t(b * kBlock),
              scratch.begin() + std::ptrdiff_t(blockEnd(b)),
              items.begin() + std::ptrdiff_t(b * kBlock));
  });
  std::nth_element(items.begin() + std::ptrdiff_t(total[0]), items.begin() + std::ptrdiff_t(k),
                   items.begin() + std::ptrdiff_t(total[0] + total[1]), less);
}

}  // namespace amrstream::render
