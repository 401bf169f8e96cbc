// Derived vectors through the library's front door: --vector grad(NAME) / -grad(NAME) and
// --frame-velocity, on leaf cells of three levels with refinement off the middle, over a domain
// whose cells are twice as tall in y as wide (physical units differ from cell units per axis).
// Oracles: the lines of -grad(f) for f = x + 2y are straight, along -(1, 2, 0) / sqrt(5);
// solid-body rotation plus a uniform drift U, seen from a frame moving at U, is rotation alone, so
// its lines keep their distance from the axis (and do not without the frame); `auto` over a box
// symmetric about the axis and tiled by whole cells is exactly U (the cells' volume-weighted mean
// of a linear field over a box they tile is its value at the box's centre, here the axis, where
// the rotation vanishes), so the tolerance is the float rounding of the cells' values.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "amrstream/dataset.hpp"
#include "amrstream/error.hpp"
#include "amrstream/field.hpp"
#include "amrstream/pathlines.hpp"
#include "amrstream/trace_job.hpp"
#include "amrstream/tracing.hpp"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const glm::dvec3 kCentre(0.5, 1.0, 0.5);  // the domain's centre: [0, 1) x [0, 2) x [0, 1)
const glm::dvec3 kDrift(0.3, -0.2, 0.1);
constexpr double kOmega = 2.0 * std::numbers::pi;  // about z

// The rotation about kCentre's z axis plus kDrift.
glm::dvec3 driftingRotation(glm::dvec3 p) {
  return glm::dvec3(-kOmega * (p.y - kCentre.y), kOmega * (p.x - kCentre.x), 0.0) + kDrift;
}

// Cells of widths 4, 2 and 1 finest cells over 32^3 finest cells (finest cells 1/32 by 1/16 by
// 1/32), the width-2 cells in [8, 24) x [4, 20) x [8, 28), the width-1 cells in [10, 18) x
// [6, 12) x [14, 22): channels f = x + 2y and the drifting rotation as velx, vely, velz, at the
// cells' centres.
amrstream::Dataset threeLevels() {
  amrstream::CellArrays cells;
  const auto inside = [](glm::ivec3 c, glm::ivec3 lo, glm::ivec3 hi) {
    return glm::all(glm::greaterThanEqual(c, lo)) && glm::all(glm::lessThan(c, hi));
  };
  const std::function<void(glm::ivec3, int)> add = [&](glm::ivec3 corner, int width) {
    const bool split = (width == 4 && inside(corner, {8, 4, 8}, {24, 20, 28})) ||
                       (width == 2 && inside(corner, {10, 6, 14}, {18, 12, 22}));
    if (split) {
      for (int i = 0; i < 8; ++i)
        add(corner + (width / 2) * glm::ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1), width / 2);
      return;
    }
    cells.corners.push_back(corner);
    cells.levels.push_back(width == 4 ? 0 : width == 2 ? 1 : 2);
  };
  for (int z = 0; z < 32; z += 4)
    for (int y = 0; y < 32; y += 4)
      for (int x = 0; x < 32; x += 4) add({x, y, z}, 4);
  cells.finestWidth = glm::dvec3(1.0 / 32.0, 1.0 / 16.0, 1.0 / 32.0);
  const std::size_t n = cells.corners.size();
  std::vector<float> f(n), vx(n), vy(n), vz(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double width = double(4 >> cells.levels[i]);
    const glm::dvec3 p = (glm::dvec3(cells.corners[i]) + 0.5 * width) * cells.finestWidth;
    f[i] = float(p.x + 2.0 * p.y);
    const glm::dvec3 v = driftingRotation(p);
    vx[i] = float(v.x);
    vy[i] = float(v.y);
    vz[i] = float(v.z);
  }
  cells.channels = {{"f", f}, {"velx", vx}, {"vely", vy}, {"velz", vz}};
  cells.source = "three-levels";
  return amrstream::fromCells(std::move(cells));
}

amrstream::FieldOptions fieldOptions(std::string vector, std::string frameVelocity,
                                     std::string interpolant = "tent") {
  amrstream::FieldOptions options;
  options.vector = std::move(vector);
  options.frameVelocity = std::move(frameVelocity);
  options.interpolant = std::move(interpolant);
  return options;
}

// Short steps (a twentieth of a finest cell) keep RK4's error on the circles far below 1e-4
// (it shrinks as the step's fourth power).
amrstream::Traces traced(const amrstream::Field& field, std::vector<glm::dvec3> seeds,
                         std::uint32_t steps, float stepSize = 0.25f) {
  amrstream::TraceSettings settings;
  settings.steps = steps;
  settings.stepSize = stepSize;
  settings.direction = "forward";
  amrstream::BackendRequest cpu;
  cpu.backend = "cpu";
  amrstream::PreparedJob job = amrstream::prepare(field, std::move(seeds), settings, cpu);
  return amrstream::trace(job).assemble();
}

// The largest change of a line's distance from the rotation axis (physical units).
double largestRadiusChange(const amrstream::Traces& traces) {
  double largest = 0.0;
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    const std::uint64_t first = traces.offsets()[line], end = traces.offsets()[line + 1];
    const auto radius = [&](std::uint64_t i) {
      const glm::dvec3 p = traces.point(i);
      return glm::length(glm::dvec2(p.x - kCentre.x, p.y - kCentre.y));
    };
    for (std::uint64_t i = first; i < end; ++i)
      largest = std::max(largest, std::abs(radius(i) - radius(first)));
  }
  return largest;
}

std::string inputError(const std::function<void()>& f) {
  try {
    f();
  } catch (const amrstream::InputError& e) {
    return e.spelled(amrstream::cliFlag);
  }
  return "no error";
}

TEST(DerivedVectors, LinesOfMinusGradOfALinearScalarAreStraightAcrossTheLevels) {
  const amrstream::Dataset dataset = threeLevels();
  ASSERT_EQ(dataset.cellsPerLevel().size(), 3u);
  const amrstream::Field field = amrstream::buildField(dataset, fieldOptions("-grad(f)", ""));
  EXPECT_EQ(field.vectorName(), "-grad(f)");
  EXPECT_EQ(field.vectorChannels()[1], "-d(f)/dy");
  EXPECT_THAT(field.pointDataNames(), ::testing::Contains("f"));
  // From the top corner of the refined cells, down through both refinements and out.
  const std::vector<glm::dvec3> seeds{{0.70, 1.45, 0.55}, {0.58, 0.95, 0.60}, {0.9, 1.9, 0.2}};
  const amrstream::Traces traces = traced(field, seeds, 400);
  const glm::dvec3 down = -glm::normalize(glm::dvec3(1.0, 2.0, 0.0));
  ASSERT_EQ(traces.lineCount(), seeds.size());
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    const std::uint64_t first = traces.offsets()[line], end = traces.offsets()[line + 1];
    EXPECT_GT(end - first, 20u) << line;
    EXPECT_EQ(traces.reasons()[line], 1) << line;  // out of the domain
    const glm::dvec3 seed = traces.point(first);
    for (std::uint64_t i = first + 1; i < end; ++i) {
      const glm::dvec3 along = traces.point(i) - seed;
      ASSERT_LT(glm::length(along - glm::dot(along, down) * down), 1e-4)
          << "line " << line << " point " << i - first;
      ASSERT_GT(glm::dot(traces.point(i) - traces.point(i - 1), down), 0.0);
    }
    // The vector is the gradient's negative per physical length: -(1, 2, 0).
    const glm::vec3 v = traces.vectors()[first];
    EXPECT_NEAR(v.x, -1.0f, 1e-4f);
    EXPECT_NEAR(v.y, -2.0f, 1e-4f);
    EXPECT_NEAR(v.z, 0.0f, 1e-4f);
  }
}

TEST(DerivedVectors, RotationWithADriftIsCirclesInTheFrameMovingWithTheDrift) {
  const amrstream::Dataset dataset = threeLevels();
  const std::vector<glm::dvec3> seeds{{0.75, 1.0, 0.5}, {0.5, 1.3, 0.6}, {0.42, 0.9, 0.7}};
  // The linear interpolant reconstructs the linear field exactly across the level jumps.
  const amrstream::Field moving =
      amrstream::buildField(dataset, fieldOptions("", "0.3,-0.2,0.1", "linear"));
  EXPECT_EQ(moving.frameVelocity(), kDrift);
  EXPECT_EQ(moving.vectorName(), "vel");
  // Finest cells are 1/32 wide; a turn is about 3000 steps of 0.05.
  EXPECT_LT(largestRadiusChange(traced(moving, seeds, 3000, 0.05f)), 1e-4);
  // In the lab frame the lines are helices about another axis.
  const amrstream::Field lab = amrstream::buildField(dataset, fieldOptions("", "", "linear"));
  EXPECT_GT(largestRadiusChange(traced(lab, seeds, 3000, 0.05f)), 0.02);
}

TEST(DerivedVectors, AutoOverTheWholeDomainRecoversTheDrift) {
  const amrstream::Field field = amrstream::buildField(threeLevels(), fieldOptions("", "auto"));
  const glm::dvec3 frame = field.frameVelocity();
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(frame[axis], kDrift[axis], 1e-6) << axis;
}

class TempDir {
 public:
  TempDir()
      : path_(fs::temp_directory_path() / ("amrstream_derived_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

// The trace job takes auto's mean over its seed box, says the velocity it found, and its lines are
// the circles of the frame moving with the drift; read deferred (an .exa's channels one at a
// time) and kept whole alike.
TEST(DerivedVectors, AutoOverASeedBoxSymmetricAboutTheAxisInATraceJob) {
  TempDir dir;
  amrstream::TraceJob job;
  job.dataset.input = amrstream::writeExaBricks(threeLevels(), dir.file("three")).string();
  job.field = fieldOptions("", "auto", "linear");
  job.seeds.box = {0.25, 0.5, 0.25, 0.75, 1.5, 0.75};  // on the widest cells' faces
  job.seeds.count = 12;
  job.trace.steps = 3000;
  job.trace.stepSize = 0.05f;
  job.trace.direction = "forward";
  job.backend.backend = "cpu";
  for (const amrstream::KeepDataset keep :
       {amrstream::KeepDataset::No, amrstream::KeepDataset::Yes}) {
    std::vector<std::string> lines;
    const amrstream::Reporter reporter{[&](const std::string& line) { lines.push_back(line); }, {}};
    amrstream::PreparedJob prepared = amrstream::prepare(job, {true, keep}, reporter);
    const glm::dvec3 frame = prepared.field().frameVelocity();
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(frame[axis], kDrift[axis], 1e-6) << axis;
    EXPECT_THAT(lines, ::testing::Contains(
                           "frame      vel relative to a frame moving at (0.3, -0.2, 0.1): auto, "
                           "the mean of vel over the seed box, weighted by cell volume"));
    EXPECT_LT(largestRadiusChange(amrstream::trace(prepared).assemble()), 1e-4);
  }
}

TEST(DerivedVectors, BadRequestsAreInputErrorsNamingTheSetting) {
  const amrstream::Dataset dataset = threeLevels();
  const auto frameError = [&](const std::string& frame) {
    return inputError([&] { amrstream::buildField(dataset, fieldOptions("", frame)); });
  };
  EXPECT_EQ(frameError("1,2"), "--frame-velocity: '1,2' is not auto nor three numbers VX,VY,VZ");
  EXPECT_EQ(frameError("1,2,3,4"),
            "--frame-velocity: '1,2,3,4' is not auto nor three numbers VX,VY,VZ");
  EXPECT_EQ(frameError("1,2,"), "--frame-velocity: '1,2,' is not auto nor three numbers VX,VY,VZ");
  EXPECT_EQ(frameError("fast"), "--frame-velocity: 'fast' is not auto nor three numbers VX,VY,VZ");
  EXPECT_EQ(frameError("nan,0,0"),
            "--frame-velocity: 'nan' in 'nan,0,0' is not a finite number within +-1e+18");
  EXPECT_EQ(frameError("0,inf,0"),
            "--frame-velocity: 'inf' in '0,inf,0' is not a finite number within +-1e+18");
  EXPECT_EQ(frameError("1,,2"),
            "--frame-velocity: '' in '1,,2' is not a finite number within +-1e+18");
  EXPECT_EQ(frameError("1e300,0,0"),
            "--frame-velocity: '1e300' in '1e300,0,0' is not a finite number within +-1e+18");
  EXPECT_EQ(frameError("0.5x,0,0"),
            "--frame-velocity: '0.5x' in '0.5x,0,0' is not a finite number within +-1e+18");

  EXPECT_EQ(inputError([&] { amrstream::buildField(dataset, fieldOptions("grad(g)", "")); }),
            "--vector: no channel 'g' in three-levels to take the gradient of (did you mean "
            "'f'?); the channels are: f, velx, vely, velz");
  EXPECT_THAT(inputError([&] { amrstream::buildField(dataset, fieldOptions("grad(", "")); }),
              HasSubstr("--vector: 'grad(' is not grad(NAME) or -grad(NAME)"));
  // The vector's own channel is a scalar too.
  EXPECT_EQ(amrstream::buildField(dataset, fieldOptions("grad(velx)", "")).vectorName(),
            "grad(velx)");
}

// A pathline's particles are the same in any frame: a frame velocity there is refused.
TEST(DerivedVectors, PathlinesRefuseAFrameVelocity) {
  amrstream::PathlineJob job;
  job.field.frameVelocity = "1,0,0";
  EXPECT_THAT(inputError([&] { amrstream::tracePathlines(job); }),
              HasSubstr("--frame-velocity: is for streamlines of one snapshot"));
}

}  // namespace
