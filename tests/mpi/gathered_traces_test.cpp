// GatheredTraces: parts of any composition read as one process's lines: forward before backward,
// each by seed id, with their points; a seed traced twice in one direction is refused.

#include "mpi/gathered_traces.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace amrstream::mpi {
namespace {

// A line of `points` points whose positions encode (seed, direction, k).
void addLine(flow::TraceSet& t, std::uint32_t seed, float direction, std::uint32_t points) {
  t.seedIds.push_back(seed);
  t.directions.push_back(direction);
  t.steps.push_back(points - 1);
  t.reasons.push_back(int(seed % 3));
  for (std::uint32_t k = 0; k < points; ++k) {
    t.positions.push_back(glm::vec3(float(seed), direction, float(k)));
    t.times.push_back(direction * float(k));
    t.vectors.push_back(glm::vec3(1.0f));
    t.channels.push_back(float(seed * 100 + k));
  }
  t.offsets.push_back(t.offsets.back() + points);
}

flow::TraceSet part() {
  flow::TraceSet t;
  t.vectorName = "vel";
  t.channelNames = {"dens"};
  return t;
}

TEST(GatheredTraces, ReadPartsInTheOrderOfOneProcess) {
  std::vector<flow::TraceSet> parts(3, part());
  // Seeds 0..5 in both directions, shared out unevenly; part 1 has none.
  for (const std::uint32_t seed : {4u, 1u, 5u}) addLine(parts[0], seed, 1.0f, seed + 2);
  for (const std::uint32_t seed : {4u, 1u, 5u}) addLine(parts[0], seed, -1.0f, seed + 1);
  for (const std::uint32_t seed : {0u, 2u, 3u}) addLine(parts[2], seed, 1.0f, seed + 2);
  for (const std::uint32_t seed : {0u, 2u, 3u}) addLine(parts[2], seed, -1.0f, seed + 1);
  const GatheredTraces gathered(std::move(parts));
  const flow::TraceSet& lines = gathered.lines();
  ASSERT_EQ(lines.lineCount(), 12u);
  EXPECT_EQ(lines.channelNames, std::vector<std::string>{"dens"});
  std::vector<float> scratch;
  for (std::size_t line = 0; line < 12; ++line) {
    const std::uint32_t seed = std::uint32_t(line % 6);
    const float direction = line < 6 ? 1.0f : -1.0f;
    EXPECT_EQ(lines.seedIds[line], seed);
    EXPECT_EQ(lines.directions[line], direction);
    const std::uint32_t points = direction > 0 ? seed + 2 : seed + 1;
    EXPECT_EQ(lines.pointCount(line), points);
    EXPECT_EQ(lines.steps[line], points - 1);
    const std::span<const float> positions =
        gathered.column(flow::PointColumn::Positions, line, scratch);
    ASSERT_EQ(positions.size(), 3u * points);
    for (std::uint32_t k = 0; k < points; ++k) {
      EXPECT_EQ(positions[3 * k], float(seed));
      EXPECT_EQ(positions[3 * k + 1], direction);
      EXPECT_EQ(positions[3 * k + 2], float(k));
    }
    const std::span<const float> dens = gathered.column(flow::PointColumn::Channels, line, scratch);
    ASSERT_EQ(dens.size(), points);
    EXPECT_EQ(dens.back(), float(seed * 100 + points - 1));
  }
  EXPECT_EQ(lines.offsets.back(), 2u * (2 + 3 + 4 + 5 + 6 + 7) - 6u);
}

TEST(GatheredTraces, RefuseASeedTracedTwiceInOneDirection) {
  std::vector<flow::TraceSet> parts(2, part());
  addLine(parts[0], 3, 1.0f, 2);
  addLine(parts[1], 3, 1.0f, 2);
  EXPECT_THROW(GatheredTraces(std::move(parts)), std::invalid_argument);
}

}  // namespace
}  // namespace amrstream::mpi
