#include "app/screenshot.hpp"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>
#include <vector>

namespace amrstream::testing {
namespace {

std::vector<std::byte> bytes(std::initializer_list<int> values) {
  std::vector<std::byte> out;
  for (int v : values) out.push_back(static_cast<std::byte>(v));
  return out;
}

TEST(ToScreenshot, SwizzlesBgraToRgbaWithOpaqueAlpha) {
  // Two pixels, blue-ish then red-ish, as a B8G8R8A8 image stores them.
  const auto texels = bytes({200, 20, 10, 0, 1, 2, 250, 128});
  const app::Screenshot shot = app::toScreenshot(texels, {2, 1}, VK_FORMAT_B8G8R8A8_UNORM);
  EXPECT_EQ(shot.width, 2u);
  EXPECT_EQ(shot.height, 1u);
  EXPECT_EQ(shot.rgba, (std::vector<uint8_t>{10, 20, 200, 255, 250, 2, 1, 255}));
  EXPECT_EQ(shot.pixel(1, 0), (std::array<uint8_t, 4>{250, 2, 1, 255}));
}

TEST(ToScreenshot, KeepsRgbaOrder) {
  const auto texels = bytes({1, 2, 3, 4, 5, 6, 7, 8});
  const app::Screenshot shot = app::toScreenshot(texels, {1, 2}, VK_FORMAT_R8G8B8A8_SRGB);
  EXPECT_EQ(shot.rgba, (std::vector<uint8_t>{1, 2, 3, 255, 5, 6, 7, 255}));
  EXPECT_EQ(shot.pixel(0, 1), (std::array<uint8_t, 4>{5, 6, 7, 255}));
}

TEST(ToScreenshot, RejectsOtherFormatsAndSizes) {
  const auto texels = bytes({1, 2, 3, 4});
  EXPECT_THROW(app::toScreenshot(texels, {1, 1}, VK_FORMAT_A2B10G10R10_UNORM_PACK32),
               std::invalid_argument);
  EXPECT_THROW(app::toScreenshot(texels, {2, 1}, VK_FORMAT_B8G8R8A8_UNORM), std::invalid_argument);
}

}  // namespace
}  // namespace amrstream::testing
