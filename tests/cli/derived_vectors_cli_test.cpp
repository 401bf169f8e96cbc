// --vector grad(NAME) / -grad(NAME) and --frame-velocity on the command line: what the summary
// says, what the outputs name, and bad values failing with exit status 2 naming the option.
// Oracles: builtin:rotation is v = w x (p - c), w = (0, 0, 2 pi), c the unit domain's centre;
// the volume-weighted mean over the cells of a box on its widest cells' faces is v at the box's
// centre: zero over the whole domain, (0, 2 pi 0.25, 0) over [0.5, 1] x [0.25, 0.75] x [0.25,
// 0.75]. On Enzo's moving7 the bulk flow of about 0.6 along the diagonal carries lines round the
// periodic box; relative to it (auto) they wrap far less often where steps follow the speed.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <regex>
#include <string>

#include "run_amrstream.hpp"
#include "temp_dir_test.hpp"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

using amrstream::testing::Outcome;

Outcome run(const std::string& arguments) { return amrstream::testing::runAmrstream(arguments); }

class DerivedVectorsCli : public amrstream::testing::TempDirTest {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string fileText(const std::string& name) const {
    std::ifstream in(path(name), std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
  }
};

const std::string kSmall = " --levels 3 --root-blocks 2 --target-cells 20000";

// The frame velocity the summary's "frame" line states.
std::vector<double> frameSaid(const std::string& output) {
  const std::regex line(
      R"(frame +\S+ relative to a frame moving at \(([^,]+), ([^,]+), ([^)]+)\))");
  std::smatch m;
  if (!std::regex_search(output, m, line)) return {};
  return {std::stod(m[1]), std::stod(m[2]), std::stod(m[3])};
}

// The polylines the "output" line counts.
long polylines(const std::string& output) {
  const std::regex line(R"(\(([0-9,]+) polylines)");
  std::smatch m;
  if (!std::regex_search(output, m, line)) return -1;
  std::string digits = m[1];
  digits.erase(std::remove(digits.begin(), digits.end(), ','), digits.end());
  return std::stol(digits);
}

TEST_F(DerivedVectorsCli, GradientsAreNamedInTheSummaryAndTheFile) {
  Outcome r =
      run("trace builtin:cloud" + kSmall +
          " --vector 'grad(dens)' --backend cpu --steps 30 --count 8 --out " + path("grad.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("vector grad(dens) = (d(dens)/dx, d(dens)/dy, d(dens)/dz)"));
  EXPECT_THAT(r.output, HasSubstr("point data dens, magx, magy, magz"));
  EXPECT_THAT(fileText("grad.vtp"), HasSubstr("Name=\"grad(dens)\""));
  // A value that starts with '-' is a value, not an option.
  r = run("trace builtin:cloud" + kSmall +
          " --vector '-grad(dens)' --backend cpu --steps 30 --count 8 --out " + path("down.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("vector -grad(dens) = (-d(dens)/dx, -d(dens)/dy, -d(dens)/dz)"));
  EXPECT_THAT(fileText("down.vtp"), HasSubstr("Name=\"-grad(dens)\""));
}

TEST_F(DerivedVectorsCli, AutoIsTheMeanOverTheSeedBoxSaidInTheSummary) {
  Outcome r =
      run("trace builtin:rotation" + kSmall +
          " --frame-velocity auto --backend cpu --steps 10 --count 4 --out " + path("t.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr(": auto, the mean of vel over the domain, weighted by cell "
                                  "volume"));
  std::vector<double> frame = frameSaid(r.output);
  ASSERT_EQ(frame.size(), 3u) << r.output;
  for (const double v : frame) EXPECT_LT(std::abs(v), 1e-5) << r.output;

  r = run("trace builtin:rotation" + kSmall +
          " --frame-velocity auto --seed-box 0.5,0.25,0.25,1,0.75,0.75 --backend cpu --steps 10 "
          "--count 4 --out " +
          path("t.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("over the seed box"));
  frame = frameSaid(r.output);
  ASSERT_EQ(frame.size(), 3u) << r.output;
  EXPECT_LT(std::abs(frame[0]), 1e-5);
  EXPECT_NEAR(frame[1], std::numbers::pi / 2.0, 1e-5);
  EXPECT_LT(std::abs(frame[2]), 1e-5);
  EXPECT_THAT(fileText("t.vtp"), HasSubstr("FrameVelocity"));

  // Given, it is said as given; resample says it too.
  r = run("trace builtin:rotation" + kSmall +
          " --frame-velocity 1,-2.5,0 --backend cpu --steps 10 --count 4 --out " + path("t.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("frame      vel relative to a frame moving at (1, -2.5, 0)\n"));
  r = run("resample builtin:cloud" + kSmall +
          " --vector 'grad(dens)' --frame-velocity 1,0,0 --dims 8 --out " + path("g.vti"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("vector grad(dens) relative to a frame moving at (1, 0, 0)"));
  EXPECT_THAT(fileText("g.vti"), HasSubstr("Name=\"grad(dens)\""));
}

TEST_F(DerivedVectorsCli, BadValuesFailNamingTheOption) {
  const std::string trace =
      "trace builtin:cloud" + kSmall + " --backend cpu --steps 5 --out " + path("t.vtp");
  const struct {
    std::string options, message;
  } cases[] = {
      {"--frame-velocity 1,2", "--frame-velocity: '1,2' is not auto nor three numbers VX,VY,VZ"},
      {"--frame-velocity nan,0,0",
       "--frame-velocity: 'nan' in 'nan,0,0' is not a finite number within +-1e+18"},
      {"--vector 'grad(Dens)'",
       "--vector: no channel 'Dens' in builtin:cloud to take the gradient of (did you mean "
       "'dens'?); the channels are: dens, magx, magy, magz"},
      {"--vector 'grad('", "--vector: 'grad(' is not grad(NAME) or -grad(NAME)"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.options);
    const Outcome r = run(trace + " " + c.options);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.message));
    EXPECT_FALSE(fs::exists(path("t.vtp")));
  }
}

// Enzo's moving7: the bulk flow, about 0.6 along the diagonal (the data's README), carries the
// lines round the periodic box, each wrap a new polyline. Its mean over the domain is auto's
// frame velocity; relative to it the background is nearly still, and in cell mode, where a step
// moves h w |v|, lines there move little: far fewer polylines.
TEST_F(DerivedVectorsCli, MovingCoreWrapsLessInItsOwnFrame) {
  const fs::path enzo =
      fs::path(AMRSTREAM_REAL_DATA_DIR) / "enzo-moving7" / "DD0010" / "moving7_0010";
  if (!fs::exists(enzo)) GTEST_SKIP() << "real data " << enzo << " is absent";
  const std::string trace =
      "trace " + enzo.string() + " --backend cpu --step-mode cell --out " + path("m.vtp");
  const Outcome lab = run(trace);
  ASSERT_EQ(lab.status, 0) << lab.output;
  const Outcome moving = run(trace + " --frame-velocity auto");
  ASSERT_EQ(moving.status, 0) << moving.output;
  EXPECT_THAT(moving.output, HasSubstr("the mean of velocity over the domain"));
  const std::vector<double> frame = frameSaid(moving.output);
  ASSERT_EQ(frame.size(), 3u) << moving.output;
  for (const double v : frame) EXPECT_NEAR(v, 0.6, 0.05) << moving.output;
  EXPECT_LT(10 * polylines(moving.output), polylines(lab.output)) << lab.output << moving.output;
}

}  // namespace
