// The integrator against analytic answers: constant fields, solid-body rotation, and each
// termination reason.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <numbers>

#include "flow/cpu_tracer.hpp"
#include "flow_test_support.hpp"

namespace amrstream::flow {
namespace {

TraceSet traceOne(const VectorVolume& volume, glm::dvec3 seed, const TraceOptions& options) {
  const glm::dvec3 seeds[] = {seed};
  return traceStreamlines(volume, seeds, options);
}

glm::vec3 point(const TraceSet& t, std::uint64_t i) { return t.positions[t.firstPoint(0) + i]; }

TEST(Integrator, ConstantFieldMovesBySteptimesCellWidthTimesVelocityEachStep) {
  const glm::vec3 v(0.5f, 0.25f, -0.125f);
  const VectorVolume volume = testing::volumeOf(testing::uniformGrid(16, [&](auto) { return v; }));
  TraceOptions options;  // cell mode, h = 0.25, level-0 cells: w = 1
  options.maxSteps = 20;
  const TraceSet t = traceOne(volume, {4.0, 4.0, 8.0}, options);
  ASSERT_EQ(t.reasons[0], AMRSTREAM_REASON_MAX_STEPS);
  ASSERT_EQ(t.pointCount(0), 21u);
  for (std::uint32_t i = 0; i < 21; ++i) {
    const glm::vec3 expected = glm::vec3(4.0f, 4.0f, 8.0f) + float(i) * 0.25f * v;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(point(t, i)[c], expected[c], 1e-5f) << "point " << i;
    EXPECT_NEAR(t.times[t.firstPoint(0) + i], 0.25f * float(i), 1e-6f);
    EXPECT_NEAR(t.vectors[t.firstPoint(0) + i].x, v.x, 1e-6f);
  }
}

TEST(Integrator, TimeModeMovesByDtTimesVelocityOnMultiLevelDataInPhysicalUnits) {
  const glm::vec3 v(-0.2f, 0.1f, 0.3f);
  testing::RandomAmrOptions layout;
  layout.levels = 4;
  const bricks::AmrField cells = testing::randomAmr(8, layout, [&](auto) { return v; });
  // The same cells with a physical transform: origin (10, 20, 30), finest cell 0.5 wide.
  const bricks::AmrField field({cells.lowers().begin(), cells.lowers().end()},
                               {cells.levels().begin(), cells.levels().end()}, cells.channels(),
                               {{10.0, 20.0, 30.0}, {0.5, 0.5, 0.5}}, "transformed");
  const VectorVolume volume = testing::volumeOf(field);
  TraceOptions options;
  options.stepMode = StepMode::Time;
  options.stepSize = 0.5f;
  options.maxSteps = 30;
  const glm::dvec3 seed(16.0, 21.0, 31.0);
  const TraceSet t = traceOne(volume, seed, options);
  ASSERT_EQ(t.pointCount(0), 31u);
  for (std::uint32_t i = 0; i < 31; ++i) {
    const glm::dvec3 expected = seed + 0.5 * double(i) * glm::dvec3(v);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(point(t, i)[c], expected[c], 1e-4) << "point " << i;
    EXPECT_NEAR(t.times[t.firstPoint(0) + i], 0.5f * float(i), 1e-5f);
  }
}

TEST(Integrator, ArcModeStepsUnitSpeedWhateverTheMagnitude) {
  const VectorVolume volume = testing::volumeOf(
      testing::uniformGrid(16, [](auto) { return glm::vec3(0.0f, 30.0f, 0.0f); }));
  TraceOptions options;
  options.stepMode = StepMode::Arc;
  options.stepSize = 0.5f;
  options.maxSteps = 10;
  const TraceSet t = traceOne(volume, {8.0, 2.0, 8.0}, options);
  ASSERT_EQ(t.pointCount(0), 11u);
  for (std::uint32_t i = 0; i < 11; ++i) {
    EXPECT_NEAR(point(t, i).y, 2.0f + 0.5f * float(i), 1e-5f);
    EXPECT_NEAR(t.times[t.firstPoint(0) + i], 0.5f * float(i), 1e-5f);  // arc length
  }
}

// Largest deviation from the seed's distance to the z axis through `centre` over the first
// revolution (cell mode's IntegrationTime is physical time); fails if the trace ends sooner.
double radiusDriftOverOneRevolution(const VectorVolume& volume, glm::dvec3 centre, double radius,
                                    double period, float h) {
  TraceOptions options;
  options.stepSize = h;
  options.maxSteps = 50000;
  const TraceSet t = traceOne(volume, centre + glm::dvec3(radius, 0.0, 0.3), options);
  std::uint64_t end = 0;
  double maxDrift = 0.0;
  while (end + 1 < t.pointCount(0) && t.times[t.firstPoint(0) + end] < float(period)) {
    ++end;
    const glm::dvec3 r = glm::dvec3(point(t, end)) - centre;
    maxDrift = std::max(maxDrift, std::abs(glm::length(glm::dvec2(r)) - radius));
  }
  EXPECT_GE(t.times[t.firstPoint(0) + end], float(period))
      << "radius " << radius << ": no full revolution";
  EXPECT_NEAR(point(t, end).z, float(centre.z + 0.3), 1e-4f);
  return maxDrift;
}

// v = omega x (p - c) about the z axis through the centre, one revolution per 100 time units:
// speeds of order 1 cell per unit time, so a cell-mode step moves about h cell widths.
constexpr double kPeriod = 100.0;
testing::VectorFunction rotationAbout(glm::dvec3 centre) {
  return [centre](glm::dvec3 p) {
    const double omega = 2.0 * std::numbers::pi / kPeriod;
    return glm::vec3(-omega * (p.y - centre.y), omega * (p.x - centre.x), 0.0);
  };
}

TEST(Integrator, SolidBodyRotationKeepsTheRadiusOnOneLevel) {
  // Inside one level the reconstruction of a linear field is exact, so only RK4 and float
  // rounding remain: after one revolution at h = 0.1 the radius holds to 1e-3 cells.
  const glm::dvec3 centre(12.0, 12.0, 4.0);
  testing::RandomAmrOptions layout;
  layout.levels = 1;
  layout.rootCells = glm::ivec3(24, 24, 8);
  const VectorVolume volume =
      testing::volumeOf(testing::randomAmr(0, layout, rotationAbout(centre)));
  for (double radius : {3.0, 6.0, 10.0})
    EXPECT_LT(radiusDriftOverOneRevolution(volume, centre, radius, kPeriod, 0.1f), 1e-3)
        << "radius " << radius;
}

TEST(Integrator, SolidBodyRotationKeepsTheRadiusOnMultiLevelData) {
  // Where levels meet, a coarse brick's stencil lacks its refined neighbours and the blend is
  // exact only for constants: the velocity error there is up to (slope x half a coarse cell).
  // Allowed drift after one revolution at h = 0.05: a tenth of the coarsest cell width (8).
  const glm::dvec3 centre(24.0, 24.0, 8.0);
  testing::RandomAmrOptions layout;
  layout.levels = 4;
  layout.rootCells = glm::ivec3(6, 6, 2);  // 48 x 48 x 16 finest cells
  const VectorVolume volume =
      testing::volumeOf(testing::randomAmr(21, layout, rotationAbout(centre)));
  for (double radius : {6.0, 12.0, 18.0})
    EXPECT_LT(radiusDriftOverOneRevolution(volume, centre, radius, kPeriod, 0.05f), 0.8)
        << "radius " << radius;
}

TEST(Integrator, LeavingTheDomainEndsAtTheLastInsidePoint) {
  const VectorVolume volume =
      testing::volumeOf(testing::uniformGrid(16, [](auto) { return glm::vec3(1.0f, 0.0f, 0.0f); }));
  TraceOptions options;
  options.stepSize = 0.3f;
  const TraceSet t = traceOne(volume, {2.0, 8.0, 8.0}, options);
  EXPECT_EQ(t.reasons[0], AMRSTREAM_REASON_OUT_OF_DOMAIN);
  const glm::vec3 last = point(t, t.pointCount(0) - 1);
  EXPECT_LT(last.x, 16.0f);                 // inside the domain [0, 16)
  EXPECT_GE(last.x + 0.3f, 16.0f - 1e-4f);  // the next step would leave it
  EXPECT_EQ(t.pointCount(0), 47u);          // 2 + 46 * 0.3 = 15.8
}

TEST(Integrator, ZeroFieldStagnatesAtTheSeed) {
  const VectorVolume volume =
      testing::volumeOf(testing::uniformGrid(8, [](auto) { return glm::vec3(0.0f); }));
  const TraceSet t = traceOne(volume, {4.0, 4.0, 4.0}, {});
  EXPECT_EQ(t.reasons[0], AMRSTREAM_REASON_STAGNATION);
  EXPECT_EQ(t.pointCount(0), 1u);
}

TEST(Integrator, SlowingBelowTheTerminalSpeedStagnates) {
  // Speed 1 - x/8 falls below 0.5 at x = 4.
  const VectorVolume volume = testing::volumeOf(
      testing::uniformGrid(16, [](glm::dvec3 p) { return glm::vec3(1.0 - p.x / 8.0, 0.0, 0.0); }));
  TraceOptions options;
  options.terminalSpeed = 0.5f;
  const TraceSet t = traceOne(volume, {1.0, 8.0, 8.0}, options);
  EXPECT_EQ(t.reasons[0], AMRSTREAM_REASON_STAGNATION);
  const std::uint64_t n = t.pointCount(0);
  EXPECT_LT(glm::length(t.vectors[t.firstPoint(0) + (n - 1)]), 0.5f);
  EXPECT_GE(glm::length(t.vectors[t.firstPoint(0) + (n - 2)]), 0.5f);
  EXPECT_NEAR(point(t, n - 1).x, 4.0f, 0.25f);
}

TEST(Integrator, MaxLengthStopsBeforeTheLimitIsPassed) {
  const VectorVolume volume =
      testing::volumeOf(testing::uniformGrid(16, [](auto) { return glm::vec3(0.0f, 0.0f, 4.0f); }));
  TraceOptions options;  // each step moves 0.25 * 4 = 1 cell
  options.maxLength = 2.6f;
  const TraceSet t = traceOne(volume, {8.0, 8.0, 1.0}, options);
  EXPECT_EQ(t.reasons[0], AMRSTREAM_REASON_MAX_LENGTH);
  EXPECT_EQ(t.pointCount(0), 3u);
  EXPECT_NEAR(point(t, 2).z, 3.0f, 1e-5f);
}

TEST(Integrator, InvalidSampleEndsWithUnexpectedValue) {
  // Two blocks with a gap; a seed on the lower face of the second block's domain has no weight.
  const bricks::AmrField field = testing::twoBlocksWithAGap();
  const TraceSet t = traceOne(testing::volumeOf(field), {7.5, 2.0, 2.0}, {});
  EXPECT_EQ(t.reasons[0], AMRSTREAM_REASON_UNEXPECTED_VALUE);
  EXPECT_EQ(t.pointCount(0), 1u);
}

TEST(Integrator, ResultsDoNotDependOnTheNumberOfThreads) {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  const VectorVolume volume = testing::volumeOf(testing::randomAmr(5, layout));
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < 200; ++i) seeds.push_back(glm::dvec3(1.0 + 0.1 * i, 12.0 - 0.05 * i, 3.3));
  TraceOptions options;
  options.maxSteps = 200;
  const TraceSet parallel = traceStreamlines(volume, seeds, options);
  TraceSet serial;
  {
    tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    serial = traceStreamlines(volume, seeds, options);
  }
  EXPECT_EQ(parallel.offsets, serial.offsets);
  EXPECT_EQ(parallel.reasons, serial.reasons);
  EXPECT_EQ(parallel.positions, serial.positions);
}

}  // namespace
}  // namespace amrstream::flow

namespace amrstream::flow {
namespace {

TEST(Integrator, EndpointsOnlyKeepsTheLastPointOfTheFullTrace) {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  const VectorVolume volume = testing::volumeOf(testing::randomAmr(
      6, layout, [](glm::dvec3 p) { return glm::vec3(0.3, 0.1 * std::sin(p.x), 0.05); }));
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < 50; ++i) seeds.push_back(glm::dvec3(0.5 + 0.2 * i, 1.0 + 0.1 * i, 2.0));
  TraceOptions options;
  options.maxSteps = 150;
  const TraceSet full = traceStreamlines(volume, seeds, options);
  options.keepHistory = false;
  const TraceSet ends = traceStreamlines(volume, seeds, options);
  ASSERT_EQ(ends.lineCount(), full.lineCount());
  for (std::size_t s = 0; s < full.lineCount(); ++s) {
    EXPECT_EQ(ends.pointCount(s), 1u);
    EXPECT_EQ(ends.seedIds[s], full.seedIds[s]);
    EXPECT_EQ(ends.steps[s], full.steps[s]);
    EXPECT_EQ(full.steps[s] + 1, full.pointCount(s));
    EXPECT_EQ(ends.reasons[s], full.reasons[s]);
    const std::size_t last = full.firstPoint(s) + (full.pointCount(s) - 1);
    EXPECT_EQ(ends.positions[ends.firstPoint(s) + 0], full.positions[last]);
    EXPECT_EQ(ends.times[ends.firstPoint(s) + 0], full.times[last]);
    EXPECT_EQ(ends.vectors[ends.firstPoint(s) + 0], full.vectors[last]);
  }
}

}  // namespace
}  // namespace amrstream::flow

namespace amrstream::flow {
namespace {

TEST(Integrator, MaxTimeShortensTheLastStepToEndOnIt) {
  const glm::vec3 v(0.5f, 0.25f, 0.0f);
  const VectorVolume volume = testing::volumeOf(testing::uniformGrid(16, [&](auto) { return v; }));
  TraceOptions options;
  options.stepMode = StepMode::Time;
  options.stepSize = 0.5f;
  options.maxTime = 2.2f;
  const TraceSet t = traceOne(volume, {4.0, 4.0, 8.0}, options);
  // Forward: times 0, 0.5, ..., 2.0, then a step of 0.2 to 2.2; backward the same, negated.
  for (std::size_t line : {0u, 1u}) {
    const float sign = line == 0 ? 1.0f : -1.0f;
    EXPECT_EQ(t.reasons[line], AMRSTREAM_REASON_MAX_TIME);
    ASSERT_EQ(t.pointCount(line), 6u);
    const std::uint64_t last = t.firstPoint(line) + 5;
    EXPECT_EQ(t.times[last], sign * 2.2f);
    EXPECT_NEAR(t.times[last - 1], sign * 2.0f, 1e-6f);
    const glm::vec3 expected = glm::vec3(4.0f, 4.0f, 8.0f) + sign * 2.2f * v;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(t.positions[last][c], expected[c], 1e-5f);
    EXPECT_EQ(t.steps[line], 5u);
  }
}

TEST(Integrator, MaxTimeInCellModeIsPhysicalTime) {
  // Level-0 cells of width 1, h = 0.25, speed 2: each cell-mode step advances time by 0.25 and
  // moves 0.5 cells; a limit of 1.1 ends with a shortened step of 0.1 (0.2 cells).
  const VectorVolume volume =
      testing::volumeOf(testing::uniformGrid(16, [](auto) { return glm::vec3(2.0f, 0.0f, 0.0f); }));
  TraceOptions options;
  options.maxTime = 1.1f;
  options.direction = Direction::Forward;
  const TraceSet t = traceOne(volume, {2.0, 8.0, 8.0}, options);
  EXPECT_EQ(t.reasons[0], AMRSTREAM_REASON_MAX_TIME);
  ASSERT_EQ(t.pointCount(0), 6u);
  EXPECT_EQ(t.times.back(), 1.1f);
  EXPECT_NEAR(t.positions.back().x, 2.0f + 2.2f, 1e-5f);
}

}  // namespace
}  // namespace amrstream::flow
