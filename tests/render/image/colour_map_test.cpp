#include "render/image/colour_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

namespace amrstream::render {
namespace {

constexpr ColourMap kAllMaps[] = {ColourMap::Viridis, ColourMap::Magma,   ColourMap::Inferno,
                                  ColourMap::Plasma,  ColourMap::Cividis, ColourMap::CoolWarm,
                                  ColourMap::RdBu,    ColourMap::Twilight};
constexpr ColourMap kSequentialMaps[] = {ColourMap::Viridis, ColourMap::Magma, ColourMap::Inferno,
                                         ColourMap::Plasma, ColourMap::Cividis};
constexpr ColourMap kDivergingMaps[] = {ColourMap::CoolWarm, ColourMap::RdBu};
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

struct PublishedEnds {
  ColourMap map;
  glm::vec3 first, last;
};

TEST(ColourMapTest, EndpointsAreThePublishedColours) {
  const PublishedEnds published[] = {
      // matplotlib 3.6.3's _cm_listed.py: the first and last entries of _viridis_data etc.
      {ColourMap::Viridis, {0.267004f, 0.004874f, 0.329415f}, {0.993248f, 0.906157f, 0.143936f}},
      {ColourMap::Magma, {0.001462f, 0.000466f, 0.013866f}, {0.987053f, 0.991438f, 0.749504f}},
      {ColourMap::Inferno, {0.001462f, 0.000466f, 0.013866f}, {0.988362f, 0.998364f, 0.644924f}},
      {ColourMap::Plasma, {0.050383f, 0.029803f, 0.527975f}, {0.940015f, 0.975158f, 0.131326f}},
      {ColourMap::Cividis, {0.0f, 0.135112f, 0.304751f}, {0.995737f, 0.909344f, 0.217772f}},
      {ColourMap::Twilight,
       {0.88575016f, 0.85000925f, 0.88797365f},
       {0.88571155f, 0.85002186f, 0.88572539f}},
      // Moreland (2009): cool (59, 76, 192) to warm (180, 4, 38).
      {ColourMap::CoolWarm, fromBytes(59, 76, 192), fromBytes(180, 4, 38)},
      // ColorBrewer's RdBu, 11 classes, reversed: #053061 to #67001f.
      {ColourMap::RdBu, fromBytes(5, 48, 97), fromBytes(103, 0, 31)},
  };
  for (const PublishedEnds& ends : published) {
    SCOPED_TRACE(colourMapName(ends.map));
    expectNear(sampleColourMap(ends.map, 0.0f), ends.first, 1e-6f);
    expectNear(sampleColourMap(ends.map, 1.0f), ends.last, 1e-6f);
  }
  EXPECT_EQ(std::size(published), std::size(kAllMaps));
  // Moreland's middle (221, 221, 221) and ColorBrewer's (247, 247, 247).
  expectNear(sampleColourMap(ColourMap::CoolWarm, 0.5f), fromBytes(221, 221, 221), 1e-6f);
  expectNear(sampleColourMap(ColourMap::RdBu, 0.5f), fromBytes(247, 247, 247), 1e-6f);
}

TEST(ColourMapTest, InteriorMatchesPublishedSamples) {
  // Entry i of matplotlib's 256-entry tables sits at t = i / 255; entry 128 is a control point.
  expectNear(sampleColourMap(ColourMap::Viridis, 128.0f / 255.0f),
             {0.127568f, 0.566949f, 0.550556f}, 1e-6f);
  expectNear(sampleColourMap(ColourMap::Magma, 128.0f / 255.0f), {0.716387f, 0.214982f, 0.47529f},
             1e-6f);
  expectNear(sampleColourMap(ColourMap::Inferno, 128.0f / 255.0f),
             {0.735683f, 0.215906f, 0.330245f}, 1e-6f);
  expectNear(sampleColourMap(ColourMap::Plasma, 128.0f / 255.0f), {0.798216f, 0.280197f, 0.469538f},
             1e-6f);
  expectNear(sampleColourMap(ColourMap::Cividis, 128.0f / 255.0f),
             {0.488697f, 0.485318f, 0.471008f}, 1e-6f);
  // twilight has 510 entries, at t = i / 509; entry 256 is a control point.
  expectNear(sampleColourMap(ColourMap::Twilight, 256.0f / 509.0f),
             {0.18774482f, 0.07725159f, 0.21387449f}, 1e-6f);
  // Entries between control points, where interpolation is furthest off: within 2/255.
  expectNear(sampleColourMap(ColourMap::Viridis, 244.0f / 255.0f),
             {0.886271f, 0.892374f, 0.095374f}, 2 * kByte);
  expectNear(sampleColourMap(ColourMap::Magma, 3.0f / 255.0f), {0.004512f, 0.00349f, 0.029965f},
             2 * kByte);
  expectNear(sampleColourMap(ColourMap::Inferno, 4.0f / 255.0f), {0.006006f, 0.004692f, 0.038558f},
             2 * kByte);
  expectNear(sampleColourMap(ColourMap::Plasma, 253.0f / 255.0f), {0.944152f, 0.961916f, 0.146861f},
             2 * kByte);
  expectNear(sampleColourMap(ColourMap::Cividis, 21.0f / 255.0f), {0.0f, 0.19095f, 0.441085f},
             2 * kByte);
  expectNear(sampleColourMap(ColourMap::Twilight, 8.0f / 509.0f),
             {0.86696016f, 0.85108961f, 0.87909767f}, 2 * kByte);
  // Moreland's table at 0.25 and 0.75.
  expectNear(sampleColourMap(ColourMap::CoolWarm, 0.25f), fromBytes(141, 176, 254), kByte);
  expectNear(sampleColourMap(ColourMap::CoolWarm, 0.75f), fromBytes(244, 154, 123), kByte);
  // ColorBrewer's classes #2166ac and #d6604d, at 0.1 and 0.8 once reversed.
  expectNear(sampleColourMap(ColourMap::RdBu, 0.1f), fromBytes(33, 102, 172), 1e-6f);
  expectNear(sampleColourMap(ColourMap::RdBu, 0.8f), fromBytes(214, 96, 77), 1e-6f);
}

TEST(ColourMapTest, SequentialMapsGetLighterMonotonically) {
  for (const ColourMap map : kSequentialMaps) {
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

TEST(ColourMapTest, DivergingMapsAreLightestInTheMiddle) {
  for (const ColourMap map : kDivergingMaps) {
    SCOPED_TRACE(colourMapName(map));
    const std::vector<glm::vec3> table = colourMapTable(map);
    std::vector<double> lightnesses;
    for (const glm::vec3 colour : table) lightnesses.push_back(lightness(colour));
    const auto lightest = std::ranges::max_element(lightnesses) - lightnesses.begin();
    EXPECT_NEAR(static_cast<double>(lightest) / static_cast<double>(table.size() - 1), 0.5, 0.1);
    for (std::ptrdiff_t i = 1; i < std::ssize(lightnesses); ++i) {
      if (i <= lightest) {
        EXPECT_GT(lightnesses[i], lightnesses[i - 1]) << "entry " << i;
      } else {
        EXPECT_LT(lightnesses[i], lightnesses[i - 1]) << "entry " << i;
      }
    }
  }
}

TEST(ColourMapTest, RdBuIsBlueAtTheStartAndRedAtTheEnd) {
  const glm::vec3 low = sampleColourMap(ColourMap::RdBu, 0.0f);
  EXPECT_GT(low.b, low.r + 0.3f);
  const glm::vec3 high = sampleColourMap(ColourMap::RdBu, 1.0f);
  EXPECT_GT(high.r, high.b + 0.2f);
}

TEST(ColourMapTest, CyclicMapEndsWhereItStarts) {
  const glm::vec3 start = sampleColourMap(ColourMap::Twilight, 0.0f);
  expectNear(sampleColourMap(ColourMap::Twilight, 1.0f), start, 2 * kByte);
  // Light at both ends, dark half-way round.
  EXPECT_LT(lightness(sampleColourMap(ColourMap::Twilight, 0.5f)), lightness(start) - 50.0);
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
  for (const ColourMap map : kAllMaps) {
    const std::string_view name = colourMapName(map);
    EXPECT_EQ(parseColourMap(name), map);
    std::string upper(name);
    std::ranges::transform(upper, upper.begin(), [](unsigned char c) { return std::toupper(c); });
    EXPECT_EQ(parseColourMap(upper), map) << upper;
  }
  EXPECT_EQ(parseColourMap("viridis"), ColourMap::Viridis);
  EXPECT_EQ(parseColourMap("magma"), ColourMap::Magma);
  EXPECT_EQ(parseColourMap("coolwarm"), ColourMap::CoolWarm);
  EXPECT_EQ(parseColourMap("CoolWarm"), ColourMap::CoolWarm);
  EXPECT_EQ(parseColourMap("RdBu"), ColourMap::RdBu);
  EXPECT_EQ(parseColourMap("twilight"), ColourMap::Twilight);
  EXPECT_EQ(parseColourMap("jet"), std::nullopt);
  EXPECT_EQ(parseColourMap(""), std::nullopt);
  EXPECT_EQ(parseColourMap("viridis "), std::nullopt);
  EXPECT_EQ(parseColourMap("viridi"), std::nullopt);
  EXPECT_EQ(parseColourMap("rdbu_r"), std::nullopt);
  EXPECT_EQ(colourMapNames(), "viridis, magma, inferno, plasma, cividis, coolwarm, rdbu, twilight");
}

}  // namespace
}  // namespace amrstream::render
