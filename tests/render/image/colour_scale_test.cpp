#include "render/image/colour_scale.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <utility>

namespace amrstream::render {
namespace {

TEST(ColourScale, LinearMapsTheRangeAffinelyAndClamps) {
  const ColourScale s{ScaleKind::Linear, -2.0, 6.0};
  EXPECT_DOUBLE_EQ(s.position(-2.0), 0.0);
  EXPECT_DOUBLE_EQ(s.position(0.0), 0.25);
  EXPECT_DOUBLE_EQ(s.position(6.0), 1.0);
  EXPECT_DOUBLE_EQ(s.position(100.0), 1.0);
  EXPECT_DOUBLE_EQ(s.position(-100.0), 0.0);
  EXPECT_TRUE(std::isnan(s.position(std::nan(""))));
  EXPECT_DOUBLE_EQ(s.valueAt(0.5), 2.0);
}

TEST(ColourScale, LogMapsEachDecadeToAnEqualStep) {
  const ColourScale s{ScaleKind::Log, 1e-2, 1e4};  // six decades
  for (int e = -2; e <= 4; ++e)
    EXPECT_NEAR(s.position(std::pow(10.0, e)), (e + 2) / 6.0, 1e-12) << "10^" << e;
  // Within a decade, equal ratios take equal steps.
  EXPECT_NEAR(s.position(20.0) - s.position(10.0), s.position(200.0) - s.position(100.0), 1e-12);
  EXPECT_DOUBLE_EQ(s.position(0.0), 0.0);  // not positive: the lower end
  EXPECT_DOUBLE_EQ(s.position(-5.0), 0.0);
  EXPECT_NEAR(s.valueAt(0.5), 10.0, 1e-9);
}

TEST(ColourScale, SymLogIsLinearInsideAndAStepPerDecadeOutside) {
  const ColourScale s{ScaleKind::SymLog, -1000.0, 1000.0, 1.0};  // coordinates -4 .. 4
  EXPECT_DOUBLE_EQ(s.position(0.0), 0.5);
  EXPECT_NEAR(s.position(0.5), 0.5 + 0.5 / 8.0, 1e-12);  // linear inside +-1
  EXPECT_NEAR(s.position(1.0), 0.5 + 1.0 / 8.0, 1e-12);
  EXPECT_NEAR(s.position(10.0), 0.5 + 2.0 / 8.0, 1e-12);
  EXPECT_NEAR(s.position(100.0), 0.5 + 3.0 / 8.0, 1e-12);
  EXPECT_NEAR(s.position(-100.0), 0.5 - 3.0 / 8.0, 1e-12);
  for (const double t : {0.0, 0.1, 0.45, 0.5, 0.63, 0.9, 1.0})
    EXPECT_NEAR(s.position(s.valueAt(t)), t, 1e-12) << t;
}

TEST(ColourScale, BadScalesAreRefusedWithTheReason) {
  EXPECT_THROW(checkScale({ScaleKind::Linear, 1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(checkScale({ScaleKind::Linear, 0.0, INFINITY}), std::invalid_argument);
  try {
    checkScale({ScaleKind::Log, 0.0, 10.0});
    FAIL() << "a log scale from 0 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("positive minimum"), std::string::npos) << e.what();
  }
  EXPECT_THROW(checkScale({ScaleKind::SymLog, -1.0, 1.0, 0.0}), std::invalid_argument);
  EXPECT_NO_THROW(checkScale({ScaleKind::SymLog, -1.0, 1.0, 0.01}));
}

TEST(ColourScale, NamesRoundTrip) {
  for (const ScaleKind kind : {ScaleKind::Linear, ScaleKind::Log, ScaleKind::SymLog})
    EXPECT_EQ(parseScaleKind(scaleKindName(kind)), kind);
  EXPECT_FALSE(parseScaleKind("logarithmic"));
}

// An axis of few ticks over a range between round values (0.011 to 0.019: no multiple of 0.01
// or 0.005 but one inside) still gets two ticks, at a smaller round step.
TEST(ScaleTicks, ARangeBetweenRoundValuesGetsAtLeastTwoTicks) {
  for (const auto& [lower, upper] : {std::pair{0.011, 0.019}, std::pair{0.13, 0.97},
                                     std::pair{-3.4, -3.1}, std::pair{1.0e6 + 0.1, 1.0e6 + 0.9}}) {
    const auto ticks = scaleTicks({ScaleKind::Linear, lower, upper}, 2);
    ASSERT_GE(ticks.size(), 2u) << lower << " to " << upper;
    for (const ScaleTick& tick : ticks) {  // inside, to rounding
      EXPECT_GE(tick.value, lower - 1e-12 * std::abs(lower));
      EXPECT_LE(tick.value, upper + 1e-12 * std::abs(upper));
    }
  }
}

TEST(ScaleTicks, LinearTicksAreRoundAndInsideTheRange) {
  const auto ticks = scaleTicks({ScaleKind::Linear, 0.13, 0.97}, 6);
  ASSERT_GE(ticks.size(), 3u);
  EXPECT_LE(ticks.size(), 6u);
  const double step = ticks[1].value - ticks[0].value;
  for (std::size_t i = 0; i < ticks.size(); ++i) {
    EXPECT_GE(ticks[i].value, 0.13);
    EXPECT_LE(ticks[i].value, 0.97);
    EXPECT_NEAR(ticks[i].value / step, std::round(ticks[i].value / step), 1e-9);
    EXPECT_DOUBLE_EQ(ticks[i].position, (ticks[i].value - 0.13) / (0.97 - 0.13));
    if (i > 0) {
      EXPECT_NEAR(ticks[i].value - ticks[i - 1].value, step, 1e-12);
    }
  }
  EXPECT_EQ(ticks[0].label, "0.2");
}

TEST(ScaleTicks, LogTicksAreDecadesAtEqualSpacing) {
  const auto ticks = scaleTicks({ScaleKind::Log, 3e-3, 5e3}, 8);
  ASSERT_EQ(ticks.size(), 6u);  // 0.01 .. 1000
  EXPECT_EQ(ticks.front().label, "0.01");
  EXPECT_EQ(ticks.back().label, "1000");
  for (std::size_t i = 1; i < ticks.size(); ++i) {
    EXPECT_NEAR(ticks[i].value / ticks[i - 1].value, 10.0, 1e-9);
    EXPECT_NEAR(ticks[i].position - ticks[i - 1].position, ticks[1].position - ticks[0].position,
                1e-12);
  }
  // Twenty decades with room for five: every fifth.
  const auto sparse = scaleTicks({ScaleKind::Log, 1e-10, 1e10}, 5);
  ASSERT_LE(sparse.size(), 5u);
  EXPECT_NEAR(sparse[1].value / sparse[0].value, 1e5, 1e-3);
}

TEST(ScaleTicks, SymLogTicksAreZeroAndDecadesOnBothSides) {
  const auto ticks = scaleTicks({ScaleKind::SymLog, -1000.0, 100.0, 1.0}, 9);
  std::vector<double> values;
  for (const ScaleTick& t : ticks) values.push_back(t.value);
  EXPECT_EQ(values, (std::vector<double>{-1000, -100, -10, -1, 0, 1, 10, 100}));
  for (std::size_t i = 1; i < ticks.size(); ++i) {
    EXPECT_LT(ticks[i - 1].position, ticks[i].position);
  }
}

}  // namespace
}  // namespace amrstream::render
