// Traces grown a few steps at a time must equal one run of all the steps: the same point counts,
// steps and reasons, and the same points up to the rounding of the stored end points.

#include "flow/progressive_traces.hpp"

#include <gtest/gtest.h>

#include "flow/seed_strategies.hpp"
#include "synth/generators.hpp"

namespace amrstream::flow {
namespace {

void expectSameTraces(const TraceSet& grown, const TraceSet& once, double tolerance) {
  ASSERT_EQ(grown.seedCount, once.seedCount);
  for (std::uint32_t s = 0; s < once.seedCount; ++s) {
    ASSERT_EQ(grown.reasons[s], once.reasons[s]) << "seed " << s;
    ASSERT_EQ(grown.pointCounts[s], once.pointCounts[s]) << "seed " << s;
    ASSERT_EQ(grown.steps[s], once.steps[s]) << "seed " << s;
    for (std::uint32_t p = 0; p < once.pointCounts[s]; ++p) {
      ASSERT_LE(glm::length(grown.positions[grown.at(s, p)] - once.positions[once.at(s, p)]),
                tolerance)
          << "seed " << s << " point " << p;
      ASSERT_NEAR(grown.times[grown.at(s, p)], once.times[once.at(s, p)],
                  1e-4f * std::max(1.0f, once.times[once.at(s, p)]));
    }
  }
}

class ProgressiveTracesTest : public ::testing::Test {
 protected:
  ProgressiveTracesTest()
      : field_(synth::generate("abc", {.levels = 3, .rootBlocks = 2, .targetCells = 30000})),
        volume_(buildVectorVolume(field_, chooseVectorChannels(field_, ""))) {}

  TraceSet grow(std::span<const glm::dvec3> seeds, const TraceOptions& options,
                std::uint32_t stepsPerRound) {
    ProgressiveTraces traces(seeds, options, volume_.vectorName);
    const TraceFunction cpu = [&](std::span<const glm::dvec3> starts, const TraceOptions& o) {
      return traceStreamlines(volume_, starts, o);
    };
    std::size_t rounds = 0, taken = 0;
    while (!traces.finished()) {
      taken += traces.advance(cpu, stepsPerRound);
      ++rounds;
    }
    EXPECT_EQ(taken, traces.stepsTaken());
    EXPECT_LE(rounds, (options.maxSteps + stepsPerRound - 1) / stepsPerRound);
    return traces.traces();
  }

  bricks::AmrField field_;
  VectorVolume volume_;
};

TEST_F(ProgressiveTracesTest, GrowingInRoundsEqualsOneRun) {
  const SeedList seeds = randomSeedsInBox(glm::dvec3(0.05), glm::dvec3(0.95), 40, 3);
  TraceOptions options;
  options.maxSteps = 150;
  const TraceSet once = traceStreamlines(volume_, seeds.points, options);
  const double cell = volume_.transform.spacing.x;
  for (std::uint32_t round : {1u, 7u, 64u, 150u, 1000u})
    expectSameTraces(grow(seeds.points, options, round), once, 1e-3 * cell);
  std::size_t outOfDomain = 0;
  for (std::int32_t r : once.reasons) outOfDomain += r == AMRSTREAM_REASON_OUT_OF_DOMAIN;
  EXPECT_GT(outOfDomain, 0u) << "some traces should end before max steps";
}

TEST_F(ProgressiveTracesTest, TheLengthLimitHoldsOverTheWholeTrace) {
  const SeedList seeds = randomSeedsInBox(glm::dvec3(0.2), glm::dvec3(0.8), 20, 5);
  TraceOptions options;
  options.maxSteps = 400;
  options.maxLength = 0.3f;
  const TraceSet once = traceStreamlines(volume_, seeds.points, options);
  expectSameTraces(grow(seeds.points, options, 9), once, 1e-3 * volume_.transform.spacing.x);
  std::size_t limited = 0;
  for (std::int32_t r : once.reasons) limited += r == AMRSTREAM_REASON_MAX_LENGTH;
  EXPECT_GT(limited, 0u) << "some traces should reach the length limit";
}

TEST(ProgressiveTraces, RefusesEndpointsOnly) {
  TraceOptions options;
  options.keepHistory = false;
  const std::vector<glm::dvec3> seeds{glm::dvec3(0.5)};
  EXPECT_THROW(ProgressiveTraces(seeds, options, "v"), std::invalid_argument);
}

}  // namespace
}  // namespace amrstream::flow
