// Integration directions against their oracles: a backward line is the forward line of the
// negated field (with IntegrationTime negated), and `both` lays lines out as vtkStreamTracer
// does (all forward lines, then all backward lines, each starting at its seed).

#include <gtest/gtest.h>

#include "flow/cpu_tracer.hpp"
#include "flow_test_support.hpp"

namespace amrstream::flow {
namespace {

testing::VectorFunction swirl(float sign) {
  return [sign](glm::dvec3 p) {
    return sign * glm::vec3(0.3 - 0.02 * p.y, 0.1 + 0.03 * p.x, 0.05 * std::sin(0.3 * p.x));
  };
}

std::vector<glm::dvec3> someSeeds() {
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < 30; ++i) seeds.push_back({1.0 + 0.7 * i, 2.0 + 0.6 * i, 1.0 + 0.25 * i});
  return seeds;
}

TEST(Directions, BackwardEqualsForwardOnTheNegatedField) {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  layout.rootCells = glm::ivec3(6, 6, 3);
  const VectorVolume field = testing::volumeOf(testing::randomAmr(4, layout, swirl(1.0f)));
  const VectorVolume negated = testing::volumeOf(testing::randomAmr(4, layout, swirl(-1.0f)));
  for (const StepMode mode : {StepMode::Cell, StepMode::Time, StepMode::Arc}) {
    SCOPED_TRACE(static_cast<int>(mode));
    TraceOptions options;
    options.stepMode = mode;
    options.stepSize = mode == StepMode::Time ? 0.5f : 0.25f;
    options.maxSteps = 200;
    options.direction = Direction::Backward;
    const TraceSet backward = traceStreamlines(field, someSeeds(), options);
    options.direction = Direction::Forward;
    const TraceSet forward = traceStreamlines(negated, someSeeds(), options);
    ASSERT_EQ(backward.offsets, forward.offsets);
    EXPECT_EQ(backward.reasons, forward.reasons);
    EXPECT_EQ(backward.positions, forward.positions);
    for (std::size_t i = 0; i < forward.times.size(); ++i) {
      ASSERT_EQ(backward.times[i], -forward.times[i]) << "point " << i;
      ASSERT_EQ(backward.vectors[i], -forward.vectors[i]) << "point " << i;
    }
    for (const float d : backward.directions) EXPECT_EQ(d, -1.0f);
    std::size_t points = 0;
    for (const std::uint32_t s : forward.steps) points += s;
    EXPECT_GT(points, 1000u);
  }
}

TEST(Directions, BothIsForwardLinesThenBackwardLinesAsVtkStreamTracer) {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  layout.rootCells = glm::ivec3(6, 6, 3);
  const VectorVolume volume = testing::volumeOf(testing::randomAmr(4, layout, swirl(1.0f)));
  const std::vector<glm::dvec3> seeds = someSeeds();
  TraceOptions options;
  options.maxSteps = 150;
  options.direction = Direction::Forward;
  const TraceSet forward = traceStreamlines(volume, seeds, options);
  options.direction = Direction::Backward;
  const TraceSet backward = traceStreamlines(volume, seeds, options);
  options.direction = Direction::Both;
  const TraceSet both = traceStreamlines(volume, seeds, options);

  const std::size_t n = seeds.size();
  ASSERT_EQ(both.lineCount(), 2 * n);
  for (std::size_t line = 0; line < 2 * n; ++line) {
    const TraceSet& part = line < n ? forward : backward;
    const std::size_t i = line % n;
    EXPECT_EQ(both.seedIds[line], i);
    EXPECT_EQ(both.directions[line], line < n ? 1.0f : -1.0f);
    EXPECT_EQ(both.reasons[line], part.reasons[i]);
    ASSERT_EQ(both.pointCount(line), part.pointCount(i));
    const std::uint64_t first = both.firstPoint(line);
    EXPECT_NEAR(both.positions[first].x, seeds[i].x, 1e-5);  // every line starts at its seed
    EXPECT_EQ(both.times[first], 0.0f);
    for (std::uint64_t k = 0; k < part.pointCount(i); ++k) {
      ASSERT_EQ(both.positions[first + k], part.positions[part.firstPoint(i) + k]);
      ASSERT_EQ(both.times[first + k], part.times[part.firstPoint(i) + k]);
      if (k > 0) {
        EXPECT_TRUE(line < n ? both.times[first + k] > 0.0f : both.times[first + k] < 0.0f);
      }
    }
  }
}

}  // namespace
}  // namespace amrstream::flow
