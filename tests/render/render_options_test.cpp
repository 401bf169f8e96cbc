// The library's checks of render options, for callers that do not come through the command line
// (whose parser refuses the same values first): image sizes, ambient-occlusion rays and frames
// beyond their bounds, and values that are not finite, each refused naming the option.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "amrstream/rendering.hpp"
#include "api/handles.hpp"
#include "api/render_scene.hpp"
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
    return inputErrorOf([&] { prepareScene(options, cells_, volume_, traces_, cells_.info()); });
  }
  std::string errorOfFrames(std::uint32_t frames) {
    return inputErrorOf([&] {
      RenderOptions o;
      o.frames = frames;
      renderImage({"auto"}, o, field_, Traces());
    });
  }

  bricks::AmrField cells_ = synth::generate("rotation", {1, 1, 512, 1, 0.0});
  flow::VectorVolume volume_;
  flow::TraceSet traces_;
  Field field_ = fieldOf({}, {}, "rotation", {}, {}, datasetOf(cells_));
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

TEST_F(RenderOptionChecks, RefusesUnknownViewsAxesProjectionsAndScales) {
  RenderOptions o;
  o.view = "front";
  EXPECT_THAT(errorOf(o), HasSubstr("--view: no view 'front'; choose one of: iso, +x"));
  o = {};
  o.view = "+x";
  o.camera = {30.0f, 20.0f};
  EXPECT_THAT(errorOf(o), HasSubstr("--view: give either --view or --camera"));
  o = {};
  o.up = "+w";
  EXPECT_THAT(errorOf(o), HasSubstr("--up: '+w': choose +x, -x"));
  o = {};
  o.fovDegrees = 170.0f;
  EXPECT_THAT(errorOf(o), HasSubstr("--fov: 170 degrees is outside 1 to 150"));
  o = {};
  o.projection = "fisheye";
  EXPECT_THAT(errorOf(o), HasSubstr("--projection: 'fisheye': choose perspective or orthographic"));
  o = {};
  o.frame = "seeds";
  EXPECT_THAT(errorOf(o), HasSubstr("--frame: 'seeds': choose traces or domain"));
  o = {};
  o.lookAt = {0.0, kNaN, 0.0};
  EXPECT_THAT(errorOf(o), HasSubstr("--look-at: nan is not a finite number"));
  o = {};
  o.colourScale = "ln";
  EXPECT_THAT(errorOf(o), HasSubstr("--colour-scale: no scale 'ln'"));
  o = {};
  o.colourScale = "log";
  o.range = {-1.0f, 10.0f};
  EXPECT_THAT(errorOf(o), HasSubstr("--range: a log scale needs a positive minimum, not -1"));
  o = {};
  o.colourScale = "symlog";
  o.symlogWidth = -2.0;
  EXPECT_THAT(errorOf(o), HasSubstr("symlog's linear width must be positive, not -2"));
  o = {};
  o.tubeRadius = 1.0f;
  o.tubeRadiusPhysical = 0.01;
  EXPECT_THAT(errorOf(o), HasSubstr("--tube-radius: give the radius in cells or in physical"));
  o = {};
  o.tubeRadiusOfView = 0.0f;
  EXPECT_THAT(errorOf(o), HasSubstr("--tube-radius-view: 0 is outside (0, 0.5]"));
}

TEST_F(RenderOptionChecks, TheDefaultTubeRadiusIsAFractionOfTheView) {
  RenderOptions o;
  o.frame = "domain";
  o.tubeRadiusOfView = 0.01f;
  const RenderScene scene = prepareScene(o, cells_, volume_, traces_, cells_.info());
  const float viewHeight =
      2.0f * scene.camera.distance * std::tan(glm::radians(scene.camera.fovYDegrees) / 2.0f);
  EXPECT_NEAR(scene.settings.tubeRadius, 0.01f * viewHeight, 1e-4f * viewHeight);
  o.zoom = 2.0f;  // half the view: half the radius
  EXPECT_NEAR(prepareScene(o, cells_, volume_, traces_, cells_.info()).settings.tubeRadius,
              0.5f * scene.settings.tubeRadius, 1e-4f * viewHeight);
}

// IntegrationTime is an arc length in `arc` mode and a time otherwise: the colour bar of
// --colour-by time shows the input's length or time unit, and nothing the input does not give.
TEST_F(RenderOptionChecks, ColouringByTimeShowsIntegrationTimesUnit) {
  DatasetInfo info;
  info.lengthUnit = "cm (code length 3.1e24 cm)";
  info.timeUnit = "s";
  EXPECT_EQ(integrationTimeUnit(flow::StepMode::Arc, info), "cm");
  EXPECT_EQ(integrationTimeUnit(flow::StepMode::Cell, info), "s");
  EXPECT_EQ(integrationTimeUnit(flow::StepMode::Time, info), "s");
  EXPECT_EQ(integrationTimeUnit(flow::StepMode::Time, DatasetInfo{}), "");
  RenderOptions o;
  o.timeUnit = "s";
  o.colourBy = "time";
  EXPECT_EQ(prepareScene(o, cells_, volume_, traces_, cells_.info()).colourUnit, "s");
  o.colourBy = "speed";
  EXPECT_EQ(prepareScene(o, cells_, volume_, traces_, cells_.info()).colourUnit, "");
  DatasetInfo declared = cells_.info();
  declared.units[traces_.vectorName] = "km/s";
  EXPECT_EQ(prepareScene(o, cells_, volume_, traces_, declared).colourUnit, "km/s");
}

TEST_F(RenderOptionChecks, StreaklinesTimesAreLabelledAsAges) {
  RenderOptions o;
  o.colourBy = "time";
  EXPECT_EQ(prepareScene(o, cells_, volume_, traces_, cells_.info()).colourLabel, "time");
  flow::TraceSet streaklines = traces_;
  streaklines.timesAreAges = true;
  EXPECT_EQ(prepareScene(o, cells_, volume_, streaklines, cells_.info()).colourLabel, "age");
  o.colourBy = "speed";
  EXPECT_EQ(prepareScene(o, cells_, volume_, streaklines, cells_.info()).colourLabel,
            "|" + traces_.vectorName + "|");
}

}  // namespace
}  // namespace amrstream
