#include "render/middle_range.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace amrstream::render {
namespace {

shared::TubeSegment segment(float a, float b) {
  shared::TubeSegment s{};
  s.valueA = a;
  s.valueB = b;
  return s;
}

TEST(MiddleRange, LeavesOutTheOutliersTheOutlineAndNaN) {
  // 1000 values 0..999 (each segment's two ends), two huge outliers, outline edges and NaN.
  std::vector<shared::TubeSegment> segments;
  for (int i = 0; i < 1000; i += 2) segments.push_back(segment(float(i), float(i + 1)));
  segments.push_back(segment(-1e6f, 1e6f));
  segments.push_back(segment(float(AMRSTREAM_OUTLINE_VALUE), float(AMRSTREAM_OUTLINE_VALUE)));
  segments.push_back(segment(NAN, NAN));
  const std::optional<ValueRange> range = middleRange(segments, 0.01, 0.99);
  ASSERT_TRUE(range);
  // 1002 values: the 1st percentile is the 11th smallest (9), the 99th the 11th largest (990).
  EXPECT_EQ(range->min, 9.0f);
  EXPECT_EQ(range->max, 990.0f);
  EXPECT_EQ(middleRange(segments, 0.0, 1.0)->min, -1e6f);
}

TEST(MiddleRange, NothingWithoutTwoDistinctValues) {
  EXPECT_FALSE(middleRange({}, 0.01, 0.99));
  const std::vector<shared::TubeSegment> flat(10, segment(3.0f, 3.0f));
  EXPECT_FALSE(middleRange(flat, 0.01, 0.99));
}

TEST(MiddleRange, SamplesLargeSetsEvenly) {
  std::vector<shared::TubeSegment> segments;
  const int n = 10 * int(kMiddleRangeSamples);
  for (int i = 0; i < n; ++i) segments.push_back(segment(float(i) / float(n), float(i) / float(n)));
  const std::optional<ValueRange> range = middleRange(segments, 0.01, 0.99);
  ASSERT_TRUE(range);
  EXPECT_NEAR(range->min, 0.01f, 1e-3f);
  EXPECT_NEAR(range->max, 0.99f, 1e-3f);
}

}  // namespace
}  // namespace amrstream::render
