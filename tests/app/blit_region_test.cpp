#include "app/blit_region.hpp"

#include <gtest/gtest.h>

namespace amrstream::testing {
namespace {

using app::BlitRegion;
using app::fitCentred;

void expectRegion(const BlitRegion& r, int x0, int y0, int x1, int y1) {
  EXPECT_EQ(r.min.x, x0);
  EXPECT_EQ(r.min.y, y0);
  EXPECT_EQ(r.max.x, x1);
  EXPECT_EQ(r.max.y, y1);
}

TEST(FitCentred, SameSizeCoversTheTarget) {
  const BlitRegion r = fitCentred({320, 240}, {320, 240});
  expectRegion(r, 0, 0, 320, 240);
  EXPECT_TRUE(r.covers({320, 240}));
}

TEST(FitCentred, SameShapeScalesToCover) {
  expectRegion(fitCentred({160, 120}, {320, 240}), 0, 0, 320, 240);
  expectRegion(fitCentred({1920, 1440}, {320, 240}), 0, 0, 320, 240);
}

TEST(FitCentred, WiderFrameGetsBarsAboveAndBelow) {
  const BlitRegion r = fitCentred({320, 120}, {320, 240});
  expectRegion(r, 0, 60, 320, 180);
  EXPECT_FALSE(r.covers({320, 240}));
}

TEST(FitCentred, TallerFrameGetsBarsLeftAndRight) {
  // 100x200 into 400x300: height 300, width 150, centred at x 125.
  expectRegion(fitCentred({100, 200}, {400, 300}), 125, 0, 275, 300);
}

TEST(FitCentred, ScaledSideRoundsToTheNearestPixel) {
  // 3:2 into 100x100: height 66.67 rounds to 67, centred at y 16.
  expectRegion(fitCentred({300, 200}, {100, 100}), 0, 16, 100, 83);
}

TEST(FitCentred, ExtremeShapesKeepAtLeastOnePixel) {
  const BlitRegion r = fitCentred({10000, 1}, {100, 100});
  EXPECT_EQ(r.width(), 100u);
  EXPECT_EQ(r.height(), 1u);
}

}  // namespace
}  // namespace amrstream::testing
