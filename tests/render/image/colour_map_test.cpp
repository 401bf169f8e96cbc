#include "render/image/colour_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace amrstream::render {
namespace {

constexpr ColourMap kAllMaps[] = {ColourMap::Viridis, ColourMap::Magma, ColourMap::CoolWarm};
constexpr float kByte = 1.0f / 255.0f;

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance) {
  EXPECT_NEAR(actual.r, expected.r, tolerance);
  EXPECT_NEAR(actual.g, expected.g, tolerance);
  EXPECT_NEAR(actual.b, expected.b, tolerance);
}

glm::vec3 fromBytes(int r, int g, int b) {
  return glm::vec3(static_cast<float>(r), static_cast<float>(g), static_cast<float>(b)) / 255.0f;
}

// CIE L* of an sRGB colour (D65 white, IEC 61966-2-1 transfer function).
double lightness(glm::vec3 srgb) {
  const auto linear = [](double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  const double y = 0.2126 * linear(srgb.r) + 0.7152 * linear(srgb.g) + 0.0722 * linear(srgb.b);
  const double f = y > 216.0 / 24389.0 ? std::cbrt(y) : (24389.0 / 27.0 * y + 16.0) / 116.0;
  return 116.0 * f - 16.0;
}

TEST(ColourMapTest, EndpointsAreThePublishedColours) {
  // matplotlib's _viridis_data and _magma_data, first and last entries.
  expectNear(sampleColourMap(ColourMap::Viridis, 0.0f), {0.267004f, 0.004874f, 0.329415f}, kByte);
  expectNear(sampleColourMap(ColourMap::Viridis, 1.0f), {0.993248f, 0.906157f, 0.143936f}, kByte);
  expectNear(sampleColourMap(ColourMap::Magma, 0.0f), {0.001462f, 0.000466f, 0.013866f}, kByte);
  expectNear(sampleColourMap(ColourMap::Magma, 1.0f), {0.987053f, 0.991438f, 0.749504f}, kByte);
  // Moreland (2009): cool (59, 76, 192) to warm (180, 4, 38) through (221, 221, 221).
  expectNear(sampleColourMap(ColourMap::CoolWarm, 0.0f), fromBytes(59, 76, 192), kByte);
  expectNear(sampleColourMap(ColourMap::CoolWarm, 0.5f), fromBytes(221, 221, 221), kByte);
  expectNear(sampleColourMap(ColourMap::CoolWarm, 1.0f), fromBytes(180, 4, 38), kByte);
}

TEST(ColourMapTest, InteriorMatchesPublishedSamples) {
  // Entry i of matplotlib's 256-entry tables sits at t = i / 255; entry 128 is a control point.
  expectNear(sampleColourMap(ColourMap::Viridis, 128.0f / 255.0f),
             {0.127568f, 0.566949f, 0.550556f}, 1e-6f);
  expectNear(sampleColourMap(ColourMap::Magma, 128.0f / 255.0f), {0.716387f, 0.214982f, 0.47529f},
             1e-6f);
  // Entries between control points, where interpolation is furthest off: within 2/255.
  expectNear(sampleColourMap(ColourMap::Viridis, 244.0f / 255.0f),
             {0.886271f, 0.892374f, 0.095374f}, 2 * kByte);
  expectNear(sampleColourMap(ColourMap::Magma, 3.0f / 255.0f), {0.004512f, 0.00349f, 0.029965f},
             2 * kByte);
  // Moreland's table at 0.25 and 0.75.
  expectNear(sampleColourMap(ColourMap::CoolWarm, 0.25f), fromBytes(141, 176, 254), kByte);
  expectNear(sampleColourMap(ColourMap::CoolWarm, 0.75f), fromBytes(244, 154, 123), kByte);
}

TEST(ColourMapTest, SequentialMapsGetLighterMonotonically) {
  for (const ColourMap map : {ColourMap::Viridis, ColourMap::Magma}) {
    const std::vector<glm::vec3> table = colourMapTable(map, 1024);
    for (std::size_t i = 1; i < table.size(); ++i) {
      EXPECT_GT(lightness(table[i]), lightness(table[i - 1]))
          << colourMapName(map) << " entry " << i;
    }
  }
}

TEST(ColourMapTest, CoolWarmIsGreyInTheMiddleBlueAtTheStartRedAtTheEnd) {
  const glm::vec3 middle = sampleColourMap(ColourMap::CoolWarm, 0.5f);
  EXPECT_LT(std::max({middle.r, middle.g, middle.b}) - std::min({middle.r, middle.g, middle.b}),
            0.02f);
  EXPECT_GT(middle.g, 0.8f);
  const glm::vec3 cool = sampleColourMap(ColourMap::CoolWarm, 0.0f);
  EXPECT_GT(cool.b, cool.r + 0.4f);
  EXPECT_GT(cool.b, cool.g + 0.4f);
  const glm::vec3 warm = sampleColourMap(ColourMap::CoolWarm, 1.0f);
  EXPECT_GT(warm.r, warm.g + 0.4f);
  EXPECT_GT(warm.r, warm.b + 0.4f);
  // Diverging: the two halves get lighter towards the middle.
  EXPECT_LT(lightness(sampleColourMap(ColourMap::CoolWarm, 0.1f)), lightness(middle));
  EXPECT_LT(lightness(sampleColourMap(ColourMap::CoolWarm, 0.9f)), lightness(middle));
}

TEST(ColourMapTest, ParameterIsClampedAndNanReadsAsZero) {
  for (const ColourMap map : kAllMaps) {
    EXPECT_EQ(sampleColourMap(map, -3.0f), sampleColourMap(map, 0.0f));
    EXPECT_EQ(sampleColourMap(map, 7.5f), sampleColourMap(map, 1.0f));
    EXPECT_EQ(sampleColourMap(map, std::numeric_limits<float>::infinity()),
              sampleColourMap(map, 1.0f));
    EXPECT_EQ(sampleColourMap(map, std::numeric_limits<float>::quiet_NaN()),
              sampleColourMap(map, 0.0f));
  }
}

TEST(ColourMapTest, InterpolatesLinearlyBetweenControls) {
  // Viridis controls at entries 0 and 8 (t = 0 and 8 / 255); a quarter of the way between them.
  const glm::vec3 a{0.267004f, 0.004874f, 0.329415f};
  const glm::vec3 b{0.277018f, 0.050344f, 0.375715f};
  expectNear(sampleColourMap(ColourMap::Viridis, 2.0f / 255.0f), a + 0.25f * (b - a), 1e-6f);
}

TEST(ColourMapTest, TableHoldsUniformSamplesFromZeroToOne) {
  for (const ColourMap map : kAllMaps) {
    const std::vector<glm::vec3> table = colourMapTable(map, 5);
    ASSERT_EQ(table.size(), 5u);
    for (std::size_t i = 0; i < 5; ++i) {
      EXPECT_EQ(table[i], sampleColourMap(map, static_cast<float>(i) / 4.0f)) << i;
    }
    EXPECT_EQ(colourMapTable(map).size(), 256u);
    EXPECT_EQ(colourMapTable(map).back(), sampleColourMap(map, 1.0f));
    EXPECT_TRUE(colourMapTable(map, 0).empty());
    ASSERT_EQ(colourMapTable(map, 1).size(), 1u);
    EXPECT_EQ(colourMapTable(map, 1)[0], sampleColourMap(map, 0.0f));
  }
}

TEST(ColourMapTest, NamesRoundTripAndUnknownNamesAreRejected) {
  for (const ColourMap map : kAllMaps) EXPECT_EQ(parseColourMap(colourMapName(map)), map);
  EXPECT_EQ(parseColourMap("viridis"), ColourMap::Viridis);
  EXPECT_EQ(parseColourMap("magma"), ColourMap::Magma);
  EXPECT_EQ(parseColourMap("coolwarm"), ColourMap::CoolWarm);
  EXPECT_EQ(parseColourMap("CoolWarm"), ColourMap::CoolWarm);
  EXPECT_EQ(parseColourMap("jet"), std::nullopt);
  EXPECT_EQ(parseColourMap(""), std::nullopt);
  EXPECT_EQ(parseColourMap("viridis "), std::nullopt);
  EXPECT_EQ(parseColourMap("viridi"), std::nullopt);
  EXPECT_EQ(colourMapNames(), "viridis, magma, coolwarm");
}

}  // namespace
}  // namespace amrstream::render
