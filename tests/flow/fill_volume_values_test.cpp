// A volume built in two steps, the layout and then the values from a channel source (one channel
// at a time, as an .exa's files give them), equals the one buildVectorVolume builds from the
// whole field, with either interpolant and with point data.

#include <gtest/gtest.h>

#include <cmath>

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

TEST(FillVolumeValues, ASourceWithTooFewValuesIsRefused) {
  const bricks::AmrField field = fieldWithDensity();
  VectorVolume volume = buildCellLayout(field);
  const ChannelSource shortSource = [](const std::string&, const ChannelUse& use) {
    use(std::vector<float>(3, 0.0f));
  };
  EXPECT_THROW(
      fillVolumeValues(volume, {{"vx", "vy", "vz"}, "v"}, {}, field.source(), shortSource),
      std::logic_error);
}

}  // namespace
}  // namespace amrstream::flow
