// The volume's default transfer function against a layout whose answer is known by hand: a
// domain of 8^3 finest cells, seven coarse cells (4 finest wide) at 1 and the eighth refined into
// 64 finest cells at 1000. By count the fine cells are the majority (the median would be 1000,
// and a range from it shows nothing); by space the coarse ones hold 7/8 of the domain.

#include "render/volume_range.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "flow/vector_volume.hpp"

namespace amrstream::render {
namespace {

struct Layout {
  flow::VectorVolume volume;
  std::vector<float> rho;
};

Layout refinedCorner(float coarse, float fine) {
  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
  std::vector<float> rho;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) {
        if (x + y + z == 0) continue;
        lowers.emplace_back(4 * x, 4 * y, 4 * z);
        levels.push_back(2);
        rho.push_back(coarse);
      }
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) {
        lowers.emplace_back(x, y, z);
        levels.push_back(0);
        rho.push_back(fine);
      }
  const std::size_t n = lowers.size();
  std::vector<Channel> channels{{"vx", std::vector<float>(n, 1.0f)},
                                {"vy", std::vector<float>(n, 0.0f)},
                                {"vz", std::vector<float>(n, 0.0f)},
                                {"rho", rho}};
  const bricks::AmrField field(std::move(lowers), std::move(levels), std::move(channels),
                               {glm::dvec3(0.0), glm::dvec3(1.0)}, "corner");
  Layout layout{flow::buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"}, {}), {}};
  layout.rho = flow::gatherScalar(field, layout.volume, "rho");
  return layout;
}

TEST(DefaultVolumeTransfer, SpansFromTheBulkBySpaceToTheDensestCells) {
  const Layout layout = refinedCorner(1.0f, 1000.0f);
  const ValueRange range = defaultVolumeRange(layout.volume, layout.rho, true);
  EXPECT_FLOAT_EQ(range.min, 0.0f);  // log10 of the value 7/8 of the space holds
  EXPECT_FLOAT_EQ(range.max, 3.0f);
  const ValueRange linear = defaultVolumeRange(layout.volume, layout.rho, false);
  EXPECT_FLOAT_EQ(linear.min, 1.0f);
  EXPECT_FLOAT_EQ(linear.max, 1000.0f);
}

TEST(DefaultVolumeTransfer, OpacityGivesAMeanOpticalDepthOfOneAcrossTheDomain) {
  const Layout layout = refinedCorner(1.0f, 1000.0f);
  // x = 0 in 7/8 of the space and 1 in 1/8; the domain is 8 finest cells wide: the mean optical
  // depth along an axis is opacity * 8 / 8.
  EXPECT_FLOAT_EQ(defaultVolumeOpacity(layout.volume, layout.rho, true, {0.0f, 3.0f}), 1.0f);
  // With the bulk halfway up the range (x = 1/2 in 7/8 of the space, 1 in 1/8), the mean of x^2
  // is 7/32 + 1/8 = 11/32, a depth of 11/4 at opacity 1.
  EXPECT_FLOAT_EQ(defaultVolumeOpacity(layout.volume, layout.rho, true, {-3.0f, 3.0f}),
                  4.0f / 11.0f);
  // Nothing above the range's bottom: the fallback.
  EXPECT_EQ(defaultVolumeOpacity(layout.volume, layout.rho, true, {3.0f, 4.0f}), kFallbackOpacity);
}

TEST(DefaultVolumeTransfer, EqualValuesGetARangeOfWidthOne) {
  const Layout layout = refinedCorner(5.0f, 5.0f);
  const ValueRange range = defaultVolumeRange(layout.volume, layout.rho, false);
  EXPECT_FLOAT_EQ(range.min, 5.0f);
  EXPECT_FLOAT_EQ(range.max, 6.0f);
}

}  // namespace
}  // namespace amrstream::render
