// Fields whose values would overflow the tracer's float32 arithmetic, and steps that are not
// finite, are named errors before any tracing: nothing infinite reaches Speed, the point data,
// the vorticity or the step.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "api/stepping.hpp"
#include "flow/value_range.hpp"
#include "flow_test_support.hpp"
#include "input_error_of.hpp"

namespace amrstream::flow {
namespace {

using ::testing::HasSubstr;

// A 4^3 grid with the constant vector (s, 0, 0), a scalar "rho" = r and the given spacing.
bricks::AmrField constantField(float s, float r = 1.0f, double spacing = 1.0) {
  const bricks::AmrField grid =
      testing::uniformGrid(4, [s](glm::dvec3) { return glm::vec3(s, 0.0f, 0.0f); });
  std::vector<Channel> channels = grid.channels();
  channels.push_back({"rho", std::vector<float>(grid.cellCount(), r)});
  return bricks::AmrField({grid.lowers().begin(), grid.lowers().end()},
                          {grid.levels().begin(), grid.levels().end()}, channels,
                          {glm::dvec3(0.0), glm::dvec3(spacing)}, "big.exa");
}

TEST(ArithmeticRange, RefusesAVectorWhoseSpeedOverflowsFloat) {
  EXPECT_THAT(testing::inputErrorOf([] { testing::volumeOf(constantField(3e38f)); }),
              HasSubstr("big.exa: the vector component 'vx' is 3e+38"));
  EXPECT_NO_THROW(testing::volumeOf(constantField(kMaxVectorComponent)));
}

// The values are checked as they are gathered in brick order; the cell named is still the first
// in cell order.
TEST(ArithmeticRange, NamesTheFirstCellWhoseComponentOverflows) {
  const bricks::AmrField grid = constantField(1.0f);
  std::vector<Channel> channels = grid.channels();
  for (Channel& channel : channels)
    if (channel.name == "vy") {
      channel.values[40] = -2e38f;
      channel.values[5] = 3e38f;
    }
  const bricks::AmrField field({grid.lowers().begin(), grid.lowers().end()},
                               {grid.levels().begin(), grid.levels().end()}, channels,
                               grid.transform(), "big.exa");
  EXPECT_THAT(testing::inputErrorOf([&] { testing::volumeOf(field); }),
              HasSubstr("big.exa: the vector component 'vy' is 3e+38 at cell 5;"));
}

TEST(ArithmeticRange, RefusesPointDataWhoseTentSumOverflowsFloat) {
  VolumeOptions options;
  options.pointData = {"rho"};
  EXPECT_THAT(testing::inputErrorOf([&] {
                buildVectorVolume(constantField(1.0f, -3e38f), {{"vx", "vy", "vz"}, "v"}, options);
              }),
              HasSubstr("the point-data channel 'rho' is -3e+38"));
}

TEST(ArithmeticRange, RefusesStepsThatAreNotPositiveAndFinite) {
  const VectorVolume volume = testing::volumeOf(constantField(1.0f));
  for (float bad : {std::numeric_limits<float>::infinity(), std::nanf(""), 0.0f, -1.0f})
    EXPECT_THAT(testing::inputErrorOf([&] { chooseStepSize(StepMode::Cell, bad, volume); }),
                HasSubstr("--step-size"));
  EXPECT_EQ(chooseStepSize(StepMode::Cell, 0.5f, volume), 0.5f);
}

TEST(ArithmeticRange, TheDefaultTimeStepNamesTheFieldWhenItLeavesFloatRange) {
  // A quarter of a 1e-30 cell crossed at 1e18: 2.5e-49, below float's smallest normal number.
  const VectorVolume fast = testing::volumeOf(constantField(1e18f, 1.0f, 1e-30));
  EXPECT_THAT(testing::inputErrorOf([&] { chooseStepSize(StepMode::Time, std::nullopt, fast); }),
              HasSubstr("give --step-size or rescale the field"));
  const VectorVolume slow = testing::volumeOf(constantField(2.0f, 1.0f, 0.5));
  EXPECT_FLOAT_EQ(chooseStepSize(StepMode::Time, std::nullopt, slow), 0.25f * 0.5f / 2.0f);
}

TEST(ArithmeticRange, RefusesAVorticityThatWouldOverflowFloat) {
  TraceSettings settings;
  settings.vorticity = true;
  const VectorVolume steep = testing::volumeOf(constantField(1e18f, 1.0f, 1e-30));
  EXPECT_THAT(testing::inputErrorOf([&] { traceOptions(settings, steep); }),
              HasSubstr("--vorticity"));
  const VectorVolume fine = testing::volumeOf(constantField(1.0f, 1.0f, 1e-30));
  EXPECT_TRUE(traceOptions(settings, fine).vorticity);
}

}  // namespace
}  // namespace amrstream::flow
