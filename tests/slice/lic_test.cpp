// The LIC against what is known of it: the noise is uniform and white; along a uniform field
// each pixel is the mean of the noise at the points a step apart along its row or column, which
// the tests compute on their own (noise values are multiples of 2^-16, so the sums are exact and
// the means within a rounding); a rotation's texture follows circles; lines stop where the data
// does; a zero field leaves the noise as it is.

#include "slice/lic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace amrstream::slice {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;
// Two units in the last place of a mean in [0.5, 1): the LIC divides in float, in two roundings.
constexpr float kRounding = 0x1p-23f;

VectorImage fieldOf(std::uint32_t width, std::uint32_t height,
                    const std::function<glm::vec2(glm::vec2)>& vectorAtCentre) {
  VectorImage field;
  field.width = width;
  field.height = height;
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x)
      field.vectors.push_back(vectorAtCentre({float(x) + 0.5f, float(y) + 0.5f}));
  field.valid.assign(field.vectors.size(), 1);
  return field;
}

float meanOf(const std::vector<float>& values) {
  double sum = 0.0;
  for (const float v : values) sum += v;
  return float(sum / double(values.size()));
}

float deviationOf(const std::vector<float>& values) {
  const double mean = meanOf(values);
  double squares = 0.0;
  for (const float v : values) squares += (v - mean) * (v - mean);
  return float(std::sqrt(squares / double(values.size())));
}

// The mean noise at the points centre + k/2, k = -20..20, of a line along an axis, that lie in
// [lower, upper): each in the pixel floor(point). `noiseAt(s)` is the noise of pixel s on the line.
float meanAlongAxis(std::uint32_t pixel, float lower, float upper,
                    const std::function<float(std::uint32_t)>& noiseAt) {
  double sum = 0.0;
  int count = 0;
  for (int k = -20; k <= 20; ++k) {
    const float point = float(pixel) + 0.5f + 0.5f * float(k);
    if (point < lower || point >= upper) continue;
    sum += noiseAt(std::uint32_t(std::floor(point)));
    ++count;
  }
  return float(sum / count);
}

TEST(LicNoise, IsAFixedUniformWhiteNoise) {
  // From an independent Python implementation: the values a GLSL twin must give.
  EXPECT_EQ(licNoise(0, 0, 1), 9072 * 0x1p-16f);
  EXPECT_EQ(licNoise(1, 0, 1), 58264 * 0x1p-16f);
  EXPECT_EQ(licNoise(0, 1, 1), 40093 * 0x1p-16f);
  EXPECT_EQ(licNoise(17, 300, 1), 43553 * 0x1p-16f);
  EXPECT_EQ(licNoise(5, 5, 42), 28666 * 0x1p-16f);
  EXPECT_EQ(licNoise(0xffffffffu, 0xffffffffu, 0xffffffffu), 26911 * 0x1p-16f);

  constexpr std::uint32_t kSize = 512;
  std::vector<float> values;
  std::size_t sameForAnotherSeed = 0;
  double sumOfRowNeighbours = 0.0, sumOfColumnNeighbours = 0.0;
  for (std::uint32_t y = 0; y < kSize; ++y) {
    for (std::uint32_t x = 0; x < kSize; ++x) {
      const float value = licNoise(x, y, 1);
      ASSERT_EQ(value, licNoise(x, y, 1));
      ASSERT_GE(value, 0.0f);
      ASSERT_LT(value, 1.0f);
      values.push_back(value);
      sameForAnotherSeed += value == licNoise(x, y, 2);
      sumOfRowNeighbours += (value - 0.5) * (licNoise(x + 1, y, 1) - 0.5);
      sumOfColumnNeighbours += (value - 0.5) * (licNoise(x, y + 1, 1) - 0.5);
    }
  }
  EXPECT_NEAR(meanOf(values), 0.5, 0.01);
  const float deviation = deviationOf(values);
  EXPECT_NEAR(deviation * deviation, 1.0 / 12.0, 0.005);
  EXPECT_LT(sameForAnotherSeed, 16u);  // 2^18 pixels, each equal by chance with odds 2^-16
  // Neighbours uncorrelated: the estimate's standard deviation is 1/512 here.
  const double pairs = double(kSize) * kSize, variance = 1.0 / 12.0;
  EXPECT_LT(std::abs(sumOfRowNeighbours / pairs / variance), 0.01);
  EXPECT_LT(std::abs(sumOfColumnNeighbours / pairs / variance), 0.01);
}

// A uniform field along the image's x (or y): every line is its row (or column), traced to
// the image's edges.
void checkUniformField(bool alongY) {
  constexpr std::uint32_t kLong = 256, kShort = 64;
  const std::uint32_t width = alongY ? kShort : kLong, height = alongY ? kLong : kShort;
  const glm::vec2 vector = alongY ? glm::vec2(0.0f, 3.0f) : glm::vec2(2.5f, 0.0f);
  const VectorImage field = fieldOf(width, height, [&](glm::vec2) { return vector; });
  LicOptions options;
  options.halfLengthPixels = 10.0f;
  options.stepPixels = 0.5f;
  options.noiseSeed = 7;
  const std::vector<float> lic = lineIntegralConvolution(field, options);
  ASSERT_EQ(lic.size(), std::size_t(width) * height);
  // s along the lines, t across them.
  const auto at = [&](std::uint32_t s, std::uint32_t t) {
    return alongY ? lic[t + std::size_t(width) * s] : lic[s + std::size_t(width) * t];
  };
  const auto noise = [&](std::uint32_t s, std::uint32_t t) {
    return alongY ? licNoise(t, s, 7) : licNoise(s, t, 7);
  };

  for (std::uint32_t t = 0; t < kShort; ++t)
    for (std::uint32_t s = 0; s < kLong; ++s)
      ASSERT_NEAR(
          at(s, t),
          meanAlongAxis(s, 0.0f, float(kLong), [&](std::uint32_t sp) { return noise(sp, t); }),
          kRounding)
          << "s " << s << " t " << t;

  double alongLines = 0.0, acrossLines = 0.0;
  std::size_t alongCount = 0, acrossCount = 0;
  for (std::uint32_t t = 0; t < kShort; ++t) {
    for (std::uint32_t s = 12; s <= 243; ++s) {
      if (s < 243) alongLines += std::abs(at(s + 1, t) - at(s, t)), ++alongCount;
      if (t + 1 < kShort) acrossLines += std::abs(at(s, t + 1) - at(s, t)), ++acrossCount;
    }
  }
  // Neighbours along a line differ by (2 n(s + 11) - n(s - 10) - n(s - 9)) / 41, noise values
  // of deviation sigma: sqrt(6) sigma / 41. Lines are independent and each is a sum with weights
  // 1 and 2 (20 times) over 41: sqrt(2 * 81) sigma / 41 between them. A ratio of 0.19.
  EXPECT_LT(alongLines / double(alongCount), 0.25 * acrossLines / double(acrossCount));
  std::vector<float> acrossAtTheMiddle;
  for (std::uint32_t t = 0; t < kShort; ++t) acrossAtTheMiddle.push_back(at(kLong / 2, t));
  EXPECT_GT(deviationOf(acrossAtTheMiddle), 0.02f);
}

TEST(Lic, AlongXEachPixelIsTheMeanOfItsRowsNoiseAStepApart) { checkUniformField(false); }

TEST(Lic, AlongYEachPixelIsTheMeanOfItsColumnsNoiseAStepApart) { checkUniformField(true); }

TEST(Lic, RotationTextureFollowsCircles) {
  constexpr std::uint32_t kSize = 256;
  const glm::vec2 centre(128.0f);  // a pixel corner
  const VectorImage field = fieldOf(
      kSize, kSize, [&](glm::vec2 p) { return glm::vec2(-(p.y - centre.y), p.x - centre.x); });
  const LicOptions options;
  const std::vector<float> lic = lineIntegralConvolution(field, options);
  // Pixels in the ring 30 <= r <= 60 whose tangent is within 0.15 radians of one of the 8
  // directions to a neighbour: that neighbour lies on nearly the same circle (within 0.25
  // pixels), the one along the radius on a circle a pixel (or diagonal) out.
  double alongCircles = 0.0, acrossCircles = 0.0;
  for (std::uint32_t y = 0; y < kSize; ++y) {
    for (std::uint32_t x = 0; x < kSize; ++x) {
      const glm::vec2 offset = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - centre;
      const float radius = glm::length(offset), angle = std::atan2(offset.y, offset.x);
      const float octant = std::round(angle / (kPi / 4.0f));
      if (radius < 30.0f || radius > 60.0f || std::abs(angle - octant * kPi / 4.0f) > 0.15f)
        continue;
      const int outX = int(std::lround(std::cos(octant * kPi / 4.0f)));
      const int outY = int(std::lround(std::sin(octant * kPi / 4.0f)));
      const auto at = [&](int dx, int dy) {
        return lic[std::size_t(int(x) + dx) + kSize * std::size_t(int(y) + dy)];
      };
      alongCircles += std::abs(at(-outY, outX) - at(0, 0));
      acrossCircles += std::abs(at(outX, outY) - at(0, 0));
    }
  }
  // About 0.31 for 30 seeds (0.29 to 0.34); neighbours along a row of test 2 give 0.19.
  EXPECT_LT(alongCircles, 0.45 * acrossCircles);

  // The midpoint rule's points lie on the circle through the pixel centre (its radius drifts by
  // h^4 / 16 r^3 a step), a chord h apart. Where a point falls within float rounding of a pixel's
  // edge, the pixel it takes may differ; that moves the mean by 1/41 a point.
  std::size_t compared = 0, equal = 0;
  float worst = 0.0f;
  for (std::uint32_t y = 0; y < kSize; ++y) {
    for (std::uint32_t x = 0; x < kSize; ++x) {
      const glm::dvec2 offset = glm::dvec2(x + 0.5, y + 0.5) - glm::dvec2(centre);
      const double radius = glm::length(offset);
      if (radius < 10.0 || radius > 110.0) continue;
      const double start = std::atan2(offset.y, offset.x);
      const double chordAngle = 2.0 * std::asin(options.stepPixels / (2.0 * radius));
      double sum = 0.0;
      for (int k = -20; k <= 20; ++k) {
        const double angle = start + k * chordAngle;
        sum += licNoise(std::uint32_t(centre.x + radius * std::cos(angle)),
                        std::uint32_t(centre.y + radius * std::sin(angle)), options.noiseSeed);
      }
      const float difference = std::abs(lic[x + kSize * y] - float(sum / 41.0));
      ++compared;
      equal += difference < 1e-6f;
      worst = std::max(worst, difference);
    }
  }
  EXPECT_GT(double(equal), 0.98 * double(compared));  // 0.994 here
  EXPECT_LE(worst, 2.0f / 41.0f);
}

TEST(Lic, LinesStopWhereTheDataDoes) {
  constexpr std::uint32_t kWidth = 64, kHeight = 16, kFirstValid = 32;
  VectorImage field = fieldOf(kWidth, kHeight, [](glm::vec2 p) {
    // The left half's vectors would turn the lines if they were used.
    return p.x < float(kFirstValid) ? glm::vec2(0.0f, 1.0f) : glm::vec2(1.0f, 0.0f);
  });
  for (std::uint32_t y = 0; y < kHeight; ++y)
    for (std::uint32_t x = 0; x < kFirstValid; ++x) field.valid[x + kWidth * y] = 0;
  const std::vector<float> lic = lineIntegralConvolution(field, LicOptions{});
  for (std::uint32_t y = 0; y < kHeight; ++y) {
    for (std::uint32_t x = 0; x < kWidth; ++x) {
      const float value = lic[x + kWidth * y];
      if (x < kFirstValid) {
        EXPECT_TRUE(std::isnan(value)) << x << ", " << y;
        continue;
      }
      EXPECT_NEAR(value,
                  meanAlongAxis(x, float(kFirstValid), float(kWidth),
                                [&](std::uint32_t s) { return licNoise(s, y, 1); }),
                  kRounding)
          << x << ", " << y;
    }
  }
}

TEST(Lic, WithoutADirectionEachPixelKeepsItsNoise) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  LicOptions options;
  options.noiseSeed = 99;
  for (const glm::vec2 vector :
       {glm::vec2(0.0f), glm::vec2(kNaN, 1.0f), glm::vec2(kInfinity, 0.0f)}) {
    const VectorImage field = fieldOf(40, 30, [&](glm::vec2) { return vector; });
    const std::vector<float> lic = lineIntegralConvolution(field, options);
    for (std::uint32_t y = 0; y < 30; ++y)
      for (std::uint32_t x = 0; x < 40; ++x)
        ASSERT_EQ(lic[x + 40 * y], licNoise(x, y, 99)) << x << ", " << y;
  }
}

TEST(Lic, RejectsMismatchedSizesAndBadOptions) {
  const VectorImage field = fieldOf(8, 4, [](glm::vec2) { return glm::vec2(1.0f, 0.0f); });
  EXPECT_EQ(lineIntegralConvolution(field, LicOptions{}).size(), 32u);
  EXPECT_TRUE(lineIntegralConvolution(VectorImage{}, LicOptions{}).empty());

  VectorImage shortVectors = field;
  shortVectors.vectors.pop_back();
  EXPECT_THROW(lineIntegralConvolution(shortVectors, LicOptions{}), std::invalid_argument);
  VectorImage longValid = field;
  longValid.valid.push_back(1);
  EXPECT_THROW(lineIntegralConvolution(longValid, LicOptions{}), std::invalid_argument);
  VectorImage wrongHeight = field;
  wrongHeight.height = 5;
  EXPECT_THROW(lineIntegralConvolution(wrongHeight, LicOptions{}), std::invalid_argument);

  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  for (const float bad : {0.0f, -1.0f, kNaN, kInfinity, -kInfinity}) {
    LicOptions badLength;
    badLength.halfLengthPixels = bad;
    EXPECT_THROW(lineIntegralConvolution(field, badLength), std::invalid_argument) << bad;
    LicOptions badStep;
    badStep.stepPixels = bad;
    EXPECT_THROW(lineIntegralConvolution(field, badStep), std::invalid_argument) << bad;
  }
  LicOptions endless;
  endless.halfLengthPixels = 1e9f;
  EXPECT_THROW(lineIntegralConvolution(field, endless), std::invalid_argument);
}

}  // namespace
}  // namespace amrstream::slice
