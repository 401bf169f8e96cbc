// The check before tracing that a request's lines fit host memory (api/trace_memory.hpp): its
// oracle is the trace itself, whose lines and points either pass the limit or stay within it.

#include "api/trace_memory.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "amrstream/error.hpp"
#include "flow/cpu_tracer.hpp"
#include "flow/trace_accumulator.hpp"
#include "flow_test_support.hpp"

namespace amrstream {
namespace {

using ::testing::HasSubstr;

constexpr int kSide = 16;  // cells: a line crosses in about 64 steps of a quarter cell

flow::VectorVolume eastwardVolume() {
  return amrstream::testing::volumeOf(
      amrstream::testing::uniformGrid(kSide, [](glm::dvec3) { return glm::vec3(1, 0, 0); }));
}

std::vector<glm::dvec3> gridSeeds(int perAxis) {
  std::vector<glm::dvec3> seeds;
  for (int k = 0; k < perAxis; ++k)
    for (int j = 0; j < perAxis; ++j)
      for (int i = 0; i < perAxis; ++i)
        seeds.push_back((glm::dvec3(i, j, k) + 0.5) * double(kSide) / double(perAxis));
  return seeds;
}

flow::TraceOptions arcOptions(std::uint64_t limit) {
  flow::TraceOptions options;
  options.stepMode = flow::StepMode::Arc;
  options.stepSize = 0.25f;
  options.maxSteps = 1000;
  options.maxResultBytes = limit;
  return options;
}

// The bytes the accumulator counts for a finished trace.
std::uint64_t heldBytes(const flow::TraceSet& traces) {
  return traces.lineCount() * flow::kHeldBytesPerLine +
         traces.pointCount() * flow::TraceSet::bytesPerPoint(traces.channelCount(), false);
}

std::string refusal(const flow::VectorVolume& volume, const std::vector<glm::dvec3>& seeds,
                    const flow::TraceOptions& options) {
  try {
    checkHostTracesFit(volume, seeds, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TraceMemory, LinesWhoseBookkeepingCannotFitAreRefusedBeforeTracing) {
  const flow::VectorVolume volume = eastwardVolume();
  const std::vector<glm::dvec3> seeds = gridSeeds(10);  // 2,000 lines
  const std::string message = refusal(volume, seeds, arcOptions(2000 * flow::kHeldBytesPerLine));
  EXPECT_THAT(message, HasSubstr("1000 seeds trace 2000 lines, which need at least"));
  EXPECT_THROW(flow::traceStreamlines(volume, seeds, arcOptions(2000 * flow::kHeldBytesPerLine)),
               InputError);
}

TEST(TraceMemory, TheSampleJudgesLinesShorterThanTheirSteps) {
  const flow::VectorVolume volume = eastwardVolume();
  const std::vector<glm::dvec3> seeds = gridSeeds(10);
  // Every line traced in full, without a limit: the oracle.
  const std::uint64_t needed = heldBytes(flow::traceStreamlines(volume, seeds, arcOptions(0)));
  const std::uint64_t worst =
      2000 * (flow::kHeldBytesPerLine + 1001 * flow::TraceSet::bytesPerPoint(0, false));
  ASSERT_LT(2 * needed, worst);  // the lines end at the domain's side, long before 1000 steps

  // Room for the lines (with a tenth to spare for the sample's error) but not for their worst
  // case: accepted, and the trace indeed fits.
  const std::uint64_t room = needed + needed / 10;
  EXPECT_EQ(refusal(volume, seeds, arcOptions(room)), "");
  EXPECT_LE(heldBytes(flow::traceStreamlines(volume, seeds, arcOptions(room))), room);

  // Too little room: refused with the sample's figures, and the trace would indeed pass it.
  const std::uint64_t tight = needed / 2;
  EXPECT_THAT(refusal(volume, seeds, arcOptions(tight)), HasSubstr("2000 lines averaging"));
  EXPECT_THROW(flow::traceStreamlines(volume, seeds, arcOptions(tight)), InputError);
}

TEST(TraceMemory, EndpointsOnlyNeedNoSample) {
  const flow::VectorVolume volume = eastwardVolume();
  const std::vector<glm::dvec3> seeds = gridSeeds(10);
  flow::TraceOptions options = arcOptions(2000 * (flow::kHeldBytesPerLine + 64));
  options.keepHistory = false;
  EXPECT_EQ(refusal(volume, seeds, options), "");
  EXPECT_NO_THROW(flow::traceStreamlines(volume, seeds, options));
}

TEST(TraceMemory, TheLimitLeavesWhatTheProcessHolds) {
  const std::uint64_t limit = hostTraceLimit();
  EXPECT_GT(limit, 0u);
  const std::vector<char> held(std::size_t(256) << 20, 1);  // 256 MiB, written: resident
  ASSERT_EQ(held.back(), 1);
  EXPECT_LE(hostTraceLimit() + (std::uint64_t(200) << 20), limit);
}

}  // namespace
}  // namespace amrstream
