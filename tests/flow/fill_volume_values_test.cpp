// A volume built in two steps, the layout and then the values from a channel source (one channel
// at a time, as an .exa's files give them), equals the one buildVectorVolume builds from the
// whole field, with either interpolant and with point data; a part cropped from a whole
// layout equals the part built from the cells.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "flow/vector_volume.hpp"
#include "flow_test_support.hpp"

namespace amrstream::flow {
namespace {

bricks::AmrField fieldWithDensity() {
  bricks::AmrField field = testing::randomAmr(4, {}, [](glm::dvec3 c) {
    return glm::vec3(std::sin(0.3 * c.x), std::cos(0.2 * c.y), 0.1 * c.z);
  });
  std::vector<float> rho(field.cellCount());
  for (std::size_t i = 0; i < rho.size(); ++i) rho[i] = 1.0f + 0.01f * float(i % 97);
  field.addChannel({"rho", std::move(rho)});
  return field;
}

TEST(FillVolumeValues, TheLayoutThenTheValuesEqualsTheWholeBuild) {
  const bricks::AmrField field = fieldWithDensity();
  const VectorChannels vector{{"vx", "vy", "vz"}, "v"};
  for (const Interpolant interpolant : {Interpolant::Tent, Interpolant::Linear}) {
    VolumeOptions options;
    options.interpolant = interpolant;
    options.pointData = {"rho"};
    const VectorVolume whole = buildVectorVolume(field, vector, options);

    VectorVolume twoSteps = buildCellLayout(field, options);
    std::vector<std::string> asked;
    const ChannelSource source = [&](const std::string& name, const ChannelUse& use) {
      asked.push_back(name);
      const std::vector<float> copy = field.channel(name).values;  // as if read from a file
      use(copy);
    };
    fillVolumeValues(twoSteps, vector, options, field.source(), source);
    EXPECT_EQ(asked, (std::vector<std::string>{"vx", "vy", "vz", "rho"}));
    EXPECT_EQ(twoSteps.values, whole.values);
    EXPECT_EQ(twoSteps.channelValues, whole.channelValues);
    EXPECT_EQ(twoSteps.vectorGradients, whole.vectorGradients);
    EXPECT_EQ(twoSteps.channelGradients, whole.channelGradients);
    EXPECT_EQ(twoSteps.channelNames, whole.channelNames);
    EXPECT_EQ(twoSteps.vectorName, whole.vectorName);
    EXPECT_EQ(twoSteps.interpolant, whole.interpolant);
    EXPECT_EQ(twoSteps.cellIds, whole.cellIds);
  }
}

// A rank's part cropped from the whole volume's bricks equals the part built from the cells,
// brick for brick, with and without periodic axes (whose images follow the kept bricks).
TEST(FillVolumeValues, APartCroppedFromTheWholeEqualsOneBuiltFromTheCells) {
  const bricks::AmrField field = fieldWithDensity();
  for (const bool periodic : {false, true}) {
    SCOPED_TRACE(periodic ? "periodic" : "bounded");
    VolumeOptions options;
    options.periodic = {periodic, periodic, false};
    const VectorVolume whole = buildCellLayout(field, options);
    const glm::dvec3 middle = 0.5 * glm::dvec3(whole.domain.lower + whole.domain.upper);
    options.keepAround = VolumeOptions::Box{glm::dvec3(whole.domain.lower) - 3.0, middle};
    const VectorVolume built = buildCellLayout(field, options);
    const VectorVolume cropped = cropCellLayout(whole, options);
    ASSERT_EQ(cropped.bricks.size(), built.bricks.size());
    ASSERT_LT(built.originalBrickCount, whole.originalBrickCount);
    EXPECT_EQ(cropped.originalBrickCount, built.originalBrickCount);
    for (std::size_t b = 0; b < built.bricks.size(); ++b)
      ASSERT_EQ(std::memcmp(&cropped.bricks[b], &built.bricks[b], sizeof(shared::Brick)), 0) << b;
    EXPECT_EQ(cropped.cellIds, built.cellIds);
    EXPECT_EQ(cropped.regions.regions.size(), built.regions.regions.size());
    EXPECT_EQ(cropped.regions.regionBricks, built.regions.regionBricks);
    EXPECT_EQ(cropped.domain.lower, built.domain.lower);
    EXPECT_EQ(cropped.domain.upper, built.domain.upper);
  }
}

TEST(FillVolumeValues, ASourceWithTooFewValuesIsRefused) {
  const bricks::AmrField field = fieldWithDensity();
  VectorVolume volume = buildCellLayout(field);
  const ChannelSource shortSource = [](const std::string&, const ChannelUse& use) {
    use(std::vector<float>(3, 0.0f));
  };
  EXPECT_THROW(fillVolumeValues(volume, {{"vx", "vy", "vz"}, "v"}, {}, field.source(), shortSource),
               std::logic_error);
}

}  // namespace
}  // namespace amrstream::flow
