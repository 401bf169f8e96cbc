#include "render/image/image.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace amrstream::render {
namespace {

TEST(ImageTest, ConstructorFillsEveryPixelRowMajor) {
  const Image image(3, 2, {1, 2, 3, 4});
  ASSERT_EQ(image.rgba.size(), 3u * 2u * 4u);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    EXPECT_EQ(image.rgba[i], 1);
    EXPECT_EQ(image.rgba[i + 3], 4);
  }
  EXPECT_EQ(Image(2, 2).at(1, 1), (Rgba8{0, 0, 0, 255}));  // default fill: opaque black
  EXPECT_TRUE(Image().empty());
  EXPECT_TRUE(Image(0, 5).empty());
}

TEST(ImageTest, SetWritesTheAddressedBytes) {
  Image image(3, 2);
  image.set(2, 1, {10, 20, 30, 40});
  EXPECT_EQ(image.at(2, 1), (Rgba8{10, 20, 30, 40}));
  const std::size_t offset = (1 * 3 + 2) * 4;  // row 1, column 2
  EXPECT_EQ(image.rgba[offset], 10);
  EXPECT_EQ(image.rgba[offset + 3], 40);
  EXPECT_EQ(image.at(1, 1), (Rgba8{}));
}

TEST(ImageTest, AccessOutsideThrows) {
  Image image(3, 2);
  EXPECT_THROW(image.at(3, 0), std::out_of_range);
  EXPECT_THROW(image.set(0, 2, {}), std::out_of_range);
  EXPECT_THROW(image.blend(std::numeric_limits<std::uint32_t>::max(), 0, {}), std::out_of_range);
  EXPECT_THROW(Image().at(0, 0), std::out_of_range);
}

TEST(ImageTest, BlendIsSourceOverAndKeepsOpaqueImagesOpaque) {
  Image image(1, 1, {200, 100, 0, 255});
  image.blend(0, 0, {0, 0, 255, 0});  // fully transparent: no change
  EXPECT_EQ(image.at(0, 0), (Rgba8{200, 100, 0, 255}));
  image.blend(0, 0, {0, 200, 100, 51});  // 20% of the way: d + 0.2 * (s - d)
  EXPECT_EQ(image.at(0, 0), (Rgba8{160, 120, 20, 255}));
  image.blend(0, 0, {7, 8, 9, 255});  // opaque: replaces
  EXPECT_EQ(image.at(0, 0), (Rgba8{7, 8, 9, 255}));

  // Over a translucent pixel (a transparent render): alpha a + b (1 - a), colour weighted by
  // each one's share: 128/255 white over 10/255 black gives alpha 0.5215 and 245 grey.
  Image translucent(1, 1, {0, 0, 0, 10});
  translucent.blend(0, 0, {255, 255, 255, 128});
  EXPECT_EQ(translucent.at(0, 0), (Rgba8{245, 245, 245, 133}));
  Image clear(1, 1, {9, 9, 9, 0});
  clear.blend(0, 0, {10, 20, 30, 77});  // over nothing: the source as it is
  EXPECT_EQ(clear.at(0, 0), (Rgba8{10, 20, 30, 77}));
}

TEST(ImageTest, ToRgba8RoundsClampsAndMapsNanToZero) {
  EXPECT_EQ(toRgba8({0.0f, 1.0f, 0.5f}), (Rgba8{0, 255, 128, 255}));
  EXPECT_EQ(toRgba8({-0.5f, 2.0f, 100.0f / 255.0f}, 7), (Rgba8{0, 255, 100, 7}));
  EXPECT_EQ(toRgba8({std::numeric_limits<float>::quiet_NaN(), 0.2f, 0.0f}).r, 0);
  EXPECT_EQ(toRgba8({0.0f, 0.2f, 0.0f}).g, 51);
}

}  // namespace
}  // namespace amrstream::render
