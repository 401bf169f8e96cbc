#include "render/image/image_compare.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

namespace amrstream::render {
namespace {

TEST(ImageCompareTest, IdenticalImagesDifferByNothing) {
  const Image a(4, 3, {1, 2, 3, 255});
  const ImageDifference d = compareImages(a, a, 0);
  EXPECT_EQ(d.meanAbsolute, 0.0);
  EXPECT_EQ(d.maxAbsolute, 0);
  EXPECT_EQ(d.fractionAbove, 0.0);
  EXPECT_EQ(compareImages(Image(), Image(), 0).fractionAbove, 0.0);
}

TEST(ImageCompareTest, MeasuresMeanMaxAndPixelsAboveTheThreshold) {
  const Image a(2, 2, {100, 100, 100, 255});
  Image b = a;
  b.set(0, 0, {110, 100, 100, 255});  // one channel off by 10
  b.set(1, 1, {97, 104, 100, 0});     // off by 3 and 4; alpha is not compared
  const ImageDifference d = compareImages(a, b, 5);
  EXPECT_DOUBLE_EQ(d.meanAbsolute, (10.0 + 3.0 + 4.0) / 12.0);
  EXPECT_EQ(d.maxAbsolute, 10);
  EXPECT_DOUBLE_EQ(d.fractionAbove, 0.25);
  EXPECT_DOUBLE_EQ(compareImages(a, b, 3).fractionAbove, 0.5);   // 4 > 3
  EXPECT_DOUBLE_EQ(compareImages(a, b, 10).fractionAbove, 0.0);  // strictly more than
  EXPECT_DOUBLE_EQ(compareImages(a, b, -1).fractionAbove, 1.0);

  const Image black(1, 1, {0, 0, 0, 255});
  const Image white(1, 1, {255, 255, 255, 255});
  EXPECT_EQ(compareImages(black, white, 0).maxAbsolute, 255);
  EXPECT_DOUBLE_EQ(compareImages(black, white, 0).meanAbsolute, 255.0);
}

TEST(ImageCompareTest, DifferentSizesThrowNamingBoth) {
  try {
    compareImages(Image(3, 5), Image(5, 3), 0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(),
                ::testing::AllOf(::testing::HasSubstr("3x5"), ::testing::HasSubstr("5x3")));
  }
}

TEST(ImageCompareTest, DescribesColoursAndCoverage) {
  Image image(4, 4, {0, 0, 0, 255});
  image.set(1, 1, {255, 0, 0, 255});
  image.set(2, 1, {255, 0, 0, 255});
  image.set(3, 3, {0, 0, 255, 255});
  image.set(0, 3, {0, 0, 0, 128});  // same RGB as the background, other alpha: another colour
  const ImageContent content = describeContent(image);
  EXPECT_EQ(content.distinctColours, 4u);
  EXPECT_DOUBLE_EQ(content.fractionNotBackground, 4.0 / 16.0);

  const ImageContent blank = describeContent(Image(8, 2, {9, 9, 9, 255}));
  EXPECT_EQ(blank.distinctColours, 1u);
  EXPECT_EQ(blank.fractionNotBackground, 0.0);
  EXPECT_EQ(describeContent(Image()).distinctColours, 0u);
}

TEST(ImageCompareTest, BackgroundIsThePixelAtTheOrigin) {
  Image image(2, 1, {5, 5, 5, 255});
  image.set(0, 0, {7, 7, 7, 255});
  EXPECT_DOUBLE_EQ(describeContent(image).fractionNotBackground, 0.5);
}

}  // namespace
}  // namespace amrstream::render
