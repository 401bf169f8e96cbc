// Tracing in rounds (streamed history) must equal tracing in one go, bit for bit on the CPU:
// RK4 keeps no state between steps but the point, IntegrationTime and the length so far, and a
// line's state passes from round to round exactly.

#include <gtest/gtest.h>

#include "flow/cpu_tracer.hpp"
#include "flow/line_plan.hpp"
#include "flow/progressive_traces.hpp"
#include "flow/round_tracer.hpp"
#include "flow/seeds.hpp"
#include "flow_test_support.hpp"
#include "synth/generators.hpp"
#include "volume_options.hpp"

namespace amrstream::flow {
namespace {

void expectIdentical(const TraceSet& a, const TraceSet& b) {
  ASSERT_EQ(a.seedIds, b.seedIds);
  ASSERT_EQ(a.directions, b.directions);
  ASSERT_EQ(a.reasons, b.reasons);
  ASSERT_EQ(a.steps, b.steps);
  ASSERT_EQ(a.offsets, b.offsets);
  ASSERT_EQ(a.positions, b.positions);
  ASSERT_EQ(a.times, b.times);
  ASSERT_EQ(a.vectors, b.vectors);
  ASSERT_EQ(a.channels.size(), b.channels.size());
  for (std::size_t i = 0; i < a.channels.size(); ++i)  // NaN where a point has no channel value
    ASSERT_TRUE(a.channels[i] == b.channels[i] ||
                (std::isnan(a.channels[i]) && std::isnan(b.channels[i])));
}

class RoundsTest : public ::testing::Test {
 protected:
  RoundsTest()
      : field_(synth::generate("cloud", {.levels = 3, .rootBlocks = 2, .targetCells = 30000})),
        volume_(buildVectorVolume(field_, chooseVectorChannels(field_, ""),
                                  testing::withPointData({"dens"}))),
        seeds_(randomSeedsInBox(domainLower(volume_), 0.999 * domainUpper(volume_), 40, 3)) {}

  bricks::AmrField field_;
  VectorVolume volume_;
  SeedList seeds_;
};

TEST_F(RoundsTest, RoundsOfAnySizeEqualOneRun) {
  TraceOptions options;
  options.maxSteps = 300;
  const TraceSet once = traceStreamlines(volume_, seeds_.points, options);
  std::size_t ended = 0;
  for (const std::int32_t r : once.reasons) ended += r != AMRSTREAM_REASON_MAX_STEPS;
  EXPECT_GT(ended, 0u) << "some lines should end before the step limit";
  for (const std::uint32_t round : {1u, 7u, 64u, 299u}) {
    SCOPED_TRACE(round);
    options.roundSteps = round;
    expectIdentical(traceStreamlines(volume_, seeds_.points, options), once);
  }
}

TEST_F(RoundsTest, ATinyMemoryBudgetGivesManyBatchesAndRoundsAndTheSameTraces) {
  TraceOptions options;
  options.maxSteps = 300;
  options.maxLength = 0.4f;  // the length so far must carry over between rounds
  const TraceSet once = traceStreamlines(volume_, seeds_.points, options);
  std::size_t limited = 0;
  for (const std::int32_t r : once.reasons) limited += r == AMRSTREAM_REASON_MAX_LENGTH;
  EXPECT_GT(limited, 0u);
  options.memoryBudget = 16 * 1024;  // a few lines of a few steps at a time
  expectIdentical(traceStreamlines(volume_, seeds_.points, options), once);
}

TEST_F(RoundsTest, EndpointsOnlyInRoundsKeepsEachLinesLastPoint) {
  TraceOptions options;
  options.maxSteps = 300;
  const TraceSet full = traceStreamlines(volume_, seeds_.points, options);
  options.keepHistory = false;
  options.roundSteps = 13;
  const TraceSet ends = traceStreamlines(volume_, seeds_.points, options);
  ASSERT_EQ(ends.lineCount(), full.lineCount());
  for (std::size_t line = 0; line < full.lineCount(); ++line) {
    ASSERT_EQ(ends.pointCount(line), 1u);
    const std::uint64_t last = full.offsets[line + 1] - 1;
    EXPECT_EQ(ends.positions[ends.firstPoint(line)], full.positions[last]);
    EXPECT_EQ(ends.times[ends.firstPoint(line)], full.times[last]);
    EXPECT_EQ(ends.steps[line], full.steps[line]);
    EXPECT_EQ(ends.reasons[line], full.reasons[line]);
  }
}

TEST_F(RoundsTest, ProgressiveTracesGrowIntoTheOneRun) {
  TraceOptions options;
  options.maxSteps = 200;
  const TraceSet once = traceStreamlines(volume_, seeds_.points, options);
  LinePlan plan = planLines(volume_, seeds_.points, options.direction);
  ProgressiveTraces traces(cpuRoundTracer(volume_, plan.states, options), plan.layout,
                           traceShape(volume_, options));
  std::size_t taken = 0, rounds = 0;
  while (!traces.finished()) {
    taken += traces.advance(9);
    ++rounds;
  }
  EXPECT_LE(rounds, (200u + 8u) / 9u);
  std::size_t steps = 0;
  for (const std::uint32_t s : once.steps) steps += s;
  EXPECT_EQ(taken, steps);
  EXPECT_EQ(traces.stepsTaken(), steps);
  expectIdentical(traces.traces(), once);
}

// What each round added (recent()) continues each line from its last point: joined, the pieces
// are the lines traced in one run.
TEST_F(RoundsTest, RecentPiecesJoinIntoTheOneRun) {
  TraceOptions options;
  options.maxSteps = 120;
  options.vorticity = true;
  const TraceSet once = traceStreamlines(volume_, seeds_.points, options);
  LinePlan plan = planLines(volume_, seeds_.points, options.direction);
  ProgressiveTraces traces(cpuRoundTracer(volume_, plan.states, options), plan.layout,
                           traceShape(volume_, options));
  std::vector<std::vector<glm::vec3>> positions(once.lineCount());
  std::vector<std::vector<float>> times(once.lineCount());
  std::vector<std::size_t> pieces(once.lineCount(), 0);
  while (!traces.finished()) {
    traces.advance(7);
    const TraceSet& recent = traces.recent();
    ASSERT_EQ(recent.vorticity.size(), recent.pointCount());
    for (std::size_t k = 0; k < recent.lineCount(); ++k) {
      // Lines are laid out forward then backward: find this piece's line by seed and direction.
      std::size_t line = 0;
      while (once.seedIds[line] != recent.seedIds[k] ||
             once.directions[line] != recent.directions[k])
        ++line;
      const std::uint64_t first = recent.offsets[k], end = recent.offsets[k + 1];
      // Every piece after the first starts at the line's last point so far.
      const std::uint64_t from = positions[line].empty() ? first : first + 1;
      if (!positions[line].empty() && end > first) {
        EXPECT_EQ(recent.positions[first], positions[line].back());
        EXPECT_EQ(recent.times[first], times[line].back());
      }
      for (std::uint64_t i = from; i < end; ++i) {
        positions[line].push_back(recent.positions[i]);
        times[line].push_back(recent.times[i]);
      }
      EXPECT_EQ(recent.steps[k], traces.traces().steps[line]);
      ++pieces[line];
    }
  }
  for (std::size_t line = 0; line < once.lineCount(); ++line) {
    const std::uint64_t first = once.offsets[line];
    ASSERT_EQ(positions[line].size(), once.pointCount(line)) << "line " << line;
    for (std::size_t k = 0; k < positions[line].size(); ++k) {
      EXPECT_EQ(positions[line][k], once.positions[first + k]);
      EXPECT_EQ(times[line][k], once.times[first + k]);
    }
  }
  EXPECT_GT(*std::max_element(pieces.begin(), pieces.end()), 5u);
}

TEST(Rounds, TracesOfAHundredThousandStepsStreamed) {
  // Solid-body rotation: the lines circle for all 1e5 steps, far more than one round holds.
  const glm::dvec3 centre(12.0, 12.0, 4.0);
  testing::RandomAmrOptions layout;
  layout.levels = 2;
  layout.rootCells = glm::ivec3(12, 12, 4);
  const VectorVolume volume = testing::volumeOf(testing::randomAmr(
      3, layout, [&](glm::dvec3 p) { return glm::vec3(-(p.y - centre.y), p.x - centre.x, 0.0); }));
  const std::vector<glm::dvec3> seeds{{17.0, 12.0, 4.1}, {12.0, 4.5, 2.0}, {15.0, 15.0, 6.0}};
  TraceOptions options;
  options.maxSteps = 100000;
  options.stepSize = 0.02f;
  const TraceSet once = traceStreamlines(volume, seeds, options);
  for (const std::int32_t r : once.reasons) EXPECT_EQ(r, AMRSTREAM_REASON_MAX_STEPS);
  options.memoryBudget = 1 << 20;  // rounds of a few thousand steps
  expectIdentical(traceStreamlines(volume, seeds, options), once);
}

}  // namespace
}  // namespace amrstream::flow
