#include "render/parallel_select.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

namespace amrstream::render {
namespace {

using Item = std::pair<float, std::uint32_t>;  // a key with many ties, then a unique index

std::vector<Item> randomItems(std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> key(0, 999);
  std::vector<Item> items(n);
  for (std::size_t i = 0; i < n; ++i) items[i] = {float(key(random)), std::uint32_t(i)};
  return items;
}

// The k-th item is std::nth_element's, no item before it is greater, none after it is less, and
// the items are the same ones.
void expectNthElement(std::vector<Item> items, std::size_t k) {
  std::vector<Item> expected = items;
  std::nth_element(expected.begin(), expected.begin() + std::ptrdiff_t(k), expected.end());
  std::vector<Item> scratch(items.size());
  parallelNthElement(std::span(items), k, std::less<Item>(), std::span(scratch));
  ASSERT_EQ(items[k], expected[k]) << "k = " << k;
  for (std::size_t i = 0; i < k; ++i) ASSERT_FALSE(items[k] < items[i]) << i;
  for (std::size_t i = k + 1; i < items.size(); ++i) ASSERT_FALSE(items[i] < items[k]) << i;
  std::sort(items.begin(), items.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(items, expected);
}

TEST(ParallelNthElement, SelectsAsStdNthElementDoes) {
  const std::vector<Item> items = randomItems(300001, 7);
  for (const std::size_t k :
       {std::size_t(0), std::size_t(1000), items.size() / 3, items.size() / 2, items.size() - 1})
    expectNthElement(items, k);
  expectNthElement(randomItems(1000, 8), 500);  // too few to share out
}

// Every sampled item has the smallest key, so the bracket of the middle holds only those and
// the selection must fall back.
TEST(ParallelNthElement, SelectsWhenTheSampleMisleads) {
  std::vector<Item> items = randomItems(409600, 9);
  for (std::size_t i = 0; i < 4096; ++i) items[i * items.size() / 4096].first = -1.0f;
  expectNthElement(items, items.size() / 2);
}

TEST(ParallelNthElement, SortedAndReversedInputs) {
  std::vector<Item> items = randomItems(200000, 10);
  std::sort(items.begin(), items.end());
  expectNthElement(items, 123456);
  std::reverse(items.begin(), items.end());
  expectNthElement(items, 54321);
}

}  // namespace
}  // namespace amrstream::render
