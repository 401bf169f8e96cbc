// Tube geometry from traces: the colour field and its range come from the traces' real points
// alone, lines of different lengths included, and periodic wraps get no tube.

#include "render/tube_geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "flow/cpu_tracer.hpp"
#include "flow/seeds.hpp"
#include "synth/generators.hpp"
#include "volume_options.hpp"

namespace amrstream::render {
namespace {

TEST(TubeGeometry, TheColourRangeIsTheRangeOverRealPoints) {
  // Lines of very different lengths, so a layout padded to the longest would hold many unused
  // slots (and a zero among the colours).
  const bricks::AmrField field = synth::generate("cloud", {3, 2, 20'000, 1});
  const flow::VectorVolume volume = flow::buildVectorVolume(
      field, flow::chooseVectorChannels(field, ""), testing::withPointData({"dens"}));
  const flow::SeedList seeds =
      flow::randomSeedsInBox(flow::domainLower(volume), 0.99 * flow::domainUpper(volume), 64, 2);
  flow::TraceOptions options;
  options.maxSteps = 500;
  const flow::TraceSet traces = flow::traceStreamlines(volume, seeds.points, options);
  std::uint64_t shortest = traces.pointCount(0), longest = 0;
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    shortest = std::min(shortest, traces.pointCount(line));
    longest = std::max(longest, traces.pointCount(line));
  }
  ASSERT_LT(3 * shortest, longest);

  ChannelValues unused;
  const ColourField dens = colourFieldOf(traces, "dens", field, volume, unused);
  ASSERT_EQ(dens.values.size(), traces.pointCount());
  const auto [lo, hi] = std::minmax_element(traces.channels.begin(), traces.channels.end());
  EXPECT_GE(*lo, 1.0f) << "the cloud's density is at least 1";
  EXPECT_EQ(rangeOf(dens.values), (ValueRange{*lo, *hi}));

  const ColourField time = colourFieldOf(traces, "time", field, volume, unused);
  const auto [tlo, thi] = std::minmax_element(traces.times.begin(), traces.times.end());
  EXPECT_LT(*tlo, 0.0f) << "backward lines";
  EXPECT_EQ(rangeOf(time.values), (ValueRange{*tlo, *thi}));
}

TEST(TubeGeometry, NoTubeCrossesTheBoxWherePeriodicLinesWrap) {
  flow::TraceSet traces;
  traces.periodic = {{true, false, false}, glm::dvec3(0.0), glm::dvec3(1.0)};
  traces.seedIds = {0};
  traces.directions = {1.0f};
  traces.steps = {3};
  traces.reasons = {AMRSTREAM_REASON_MAX_STEPS};
  traces.offsets = {0, 4};
  for (const float x : {0.8f, 0.95f, 0.05f, 0.2f}) {
    traces.positions.push_back({x, 0.5f, 0.5f});
    traces.times.push_back(0.0f);
    traces.vectors.push_back({1.0f, 0.0f, 0.0f});
  }
  const ColourField colour{"speed", std::vector<float>(4, 1.0f)};
  const std::vector<shared::TubeSegment> segments =
      buildTubeSegments(traces, colour, WorldTransform{});
  ASSERT_EQ(segments.size(), 2u);  // 0.8-0.95 and 0.05-0.2, not 0.95-0.05
  EXPECT_EQ(segments[0].b.x, 0.95f);
  EXPECT_EQ(segments[1].a.x, 0.05f);
}

}  // namespace
}  // namespace amrstream::render
