// The library's checks of render options, for callers that do not come through the command line
// (whose parser refuses the same values first): image sizes, ambient-occlusion rays and frames
// beyond their bounds, and values that are not finite, each refused naming the option.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "amrstream/rendering.hpp"
#include "input_error_of.hpp"
#include "synth/generators.hpp"

namespace amrstream {
namespace {

using ::testing::HasSubstr;
using testing::inputErrorOf;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

class RenderOptionChecks : public ::testing::Test {
 protected:
  std::string errorOf(const RenderOptions& options) {
    return inputErrorOf([&] { prepareScene(options, cells_, volume_, traces_); });
  }
  std::string errorOfFrames(std::uint32_t frames) {
    return inputErrorOf([&] {
      renderImage({"auto"}, RenderOptions{}, cells_, volume_, traces_, frames, false);
    });
  }

  Dataset cells_ = synth::generate("rotation", {1, 1, 512, 1, 0.0});
  flow::VectorVolume volume_;
  flow::TraceSet traces_;
};

TEST_F(RenderOptionChecks, RefusesSizesAndCountsBeyondTheirBounds) {
  RenderOptions o;
  o.width = 8;
  EXPECT_THAT(errorOf(o), HasSubstr("--width: 8 pixels is outside the range 16 to 16384"));
  o = {};
  o.height = 20000;
  EXPECT_THAT(errorOf(o), HasSubstr("--height: 20000 pixels is outside"));
  o = {};
  o.aoSamples = 4294967295u;
  EXPECT_THAT(errorOf(o), HasSubstr("--ao-samples: 4294967295 rays per pixel and frame are more "
                                    "than 256"));
  EXPECT_THAT(errorOfFrames(0), HasSubstr("--frames: 0 is outside the range 1 to 4096"));
  EXPECT_THAT(errorOfFrames(4294967295u), HasSubstr("--frames: 4294967295 is outside"));
}

TEST_F(RenderOptionChecks, RefusesValuesThatAreNotFinite) {
  RenderOptions o;
  o.camera = {kNaN, 20.0f};
  EXPECT_THAT(errorOf(o), HasSubstr("--camera: nan is not a finite number"));
  o.camera = {30.0f, 20.0f, kInf};
  EXPECT_THAT(errorOf(o), HasSubstr("--camera: inf is not a finite number"));
  o = {};
  o.viewBox = {0, 0, 0, 1, 1, std::numeric_limits<double>::infinity()};
  EXPECT_THAT(errorOf(o), HasSubstr("--view-box: inf is not a finite number"));
  o = {};
  o.tubeRadius = kInf;
  EXPECT_THAT(errorOf(o), HasSubstr("--tube-radius: must be positive and finite"));
  o = {};
  o.volumeOpacity = kNaN;
  EXPECT_THAT(errorOf(o), HasSubstr("--volume-opacity: nan is not a finite number >= 0"));
}

}  // namespace
}  // namespace amrstream
