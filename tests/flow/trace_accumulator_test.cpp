// The accumulator and StoredTraces gather every point column, precise positions' low parts
// included, from rounds that each hold a few points of many lines.

#include "flow/trace_accumulator.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "amrstream/error.hpp"

namespace amrstream::flow {
namespace {

constexpr std::uint32_t kLines = 3;

// Point k of line `line`: 1e-9 apart along a line, finer than float32 resolves.
glm::dvec3 exactPoint(std::uint32_t line, std::uint32_t k) {
  return {0.3712345678901 + 1e-9 * k + 1e-6 * line, 0.5 - 1e-9 * k, 0.25 + 1e-10 * line};
}

// What a line did in a round: `points` new points, ending with `reason` (or still running).
struct Emitted {
  std::uint32_t line;
  std::uint32_t points;
  std::int32_t reason = AMRSTREAM_REASON_RUNNING;
};

// A round in which the lines emit their next points; `next` counts each line's points so far.
RoundBlock roundOf(const std::vector<Emitted>& emitted, std::vector<std::uint32_t>& next,
                   bool precise) {
  RoundBlock round;
  for (const Emitted& e : emitted) {
    round.lines.push_back({e.line, e.points, next[e.line] + e.points, e.reason});
    for (std::uint32_t k = next[e.line]; k < next[e.line] + e.points; ++k) {
      const SplitPosition split = splitPosition(exactPoint(e.line, k));
      round.positions.push_back(split.high);
      if (precise) round.positionsLow.push_back(split.low);
      round.times.push_back(float(100 * e.line + k));
      round.vectors.push_back({float(k), float(e.line), 1.0f});
      round.channels.push_back(float(10 * e.line + k));
    }
    next[e.line] += e.points;
  }
  return round;
}

// Lines of 3, 4 and 3 points over three rounds, in a different thread order each round.
std::vector<RoundBlock> interleavedRounds(bool precise) {
  std::vector<std::uint32_t> next(kLines, 0);
  std::vector<RoundBlock> rounds;
  rounds.push_back(roundOf({{0, 2}, {1, 1}, {2, 0}}, next, precise));
  rounds.push_back(roundOf({{1, 3}, {2, 2}, {0, 1, AMRSTREAM_REASON_MAX_STEPS}}, next, precise));
  rounds.push_back(
      roundOf({{2, 1, AMRSTREAM_REASON_OUT_OF_DOMAIN}, {1, 0, AMRSTREAM_REASON_STAGNATION}}, next,
              precise));
  return rounds;
}

// The same lines assembled by hand, line after line.
TraceSet byHand(bool precise) {
  TraceSet t;
  t.vectorName = "v";
  t.channelNames = {"dens"};
  t.precisePositions = precise;
  t.seedIds = {0, 1, 2};
  t.directions = {1.0f, 1.0f, 1.0f};
  const std::uint32_t counts[kLines] = {3, 4, 3};
  for (std::uint32_t line = 0; line < kLines; ++line) {
    t.offsets.push_back(t.offsets.back() + counts[line]);
    for (std::uint32_t k = 0; k < counts[line]; ++k) {
      const SplitPosition split = splitPosition(exactPoint(line, k));
      t.positions.push_back(split.high);
      if (precise) t.positionsLow.push_back(split.low);
      t.times.push_back(float(100 * line + k));
      t.vectors.push_back({float(k), float(line), 1.0f});
      t.channels.push_back(float(10 * line + k));
    }
  }
  return t;
}

TraceAccumulator accumulatorFor(const TraceSet& shape) {
  return TraceAccumulator({{0, 1, 2}, {1.0f, 1.0f, 1.0f}}, shape);
}

TraceAccumulator accumulated(bool precise) {
  TraceAccumulator accumulator = accumulatorFor(byHand(false));
  for (RoundBlock& round : interleavedRounds(precise)) accumulator.add(std::move(round));
  return accumulator;
}

void expectSamePoints(const TraceSet& a, const TraceSet& b) {
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.precisePositions, b.precisePositions);
  EXPECT_TRUE(a.positions == b.positions);
  EXPECT_TRUE(a.positionsLow == b.positionsLow);
  EXPECT_TRUE(a.times == b.times);
  EXPECT_TRUE(a.vectors == b.vectors);
  EXPECT_TRUE(a.channels == b.channels);
}

TEST(TraceAccumulator, AssemblesPrecisePositionsLineAfterLine) {
  const TraceSet assembled = accumulated(true).assemble();
  expectSamePoints(assembled, byHand(true));
  EXPECT_EQ(assembled.reasons,
            (std::vector<std::int32_t>{AMRSTREAM_REASON_MAX_STEPS, AMRSTREAM_REASON_STAGNATION,
                                       AMRSTREAM_REASON_OUT_OF_DOMAIN}));
  EXPECT_EQ(assembled.steps, (std::vector<std::uint32_t>{3, 4, 3}));
}

TEST(TraceAccumulator, SnapshotsKeepTheLowParts) {
  expectSamePoints(accumulated(true).snapshot(), byHand(true));
}

TEST(TraceAccumulator, StoredTracesReadLowPartsLineByLineAsATraceSetDoes) {
  const StoredTraces stored = accumulated(true).store();
  const TraceSet expected = byHand(true);
  const TraceSetView view(expected);
  EXPECT_TRUE(stored.lines().precisePositions);
  for (std::size_t line = 0; line < kLines; ++line) {
    SCOPED_TRACE(line);
    std::vector<float> a, b;
    const std::span<const float> storedLow = stored.column(PointColumn::PositionsLow, line, a);
    const std::span<const float> viewLow = view.column(PointColumn::PositionsLow, line, b);
    ASSERT_EQ(storedLow.size(), 3 * expected.pointCount(line));
    EXPECT_TRUE(std::equal(storedLow.begin(), storedLow.end(), viewLow.begin(), viewLow.end()));
    std::vector<double> c, d;
    const std::span<const double> storedExact = exactPositions(stored, line, c);
    const std::span<const double> viewExact = exactPositions(view, line, d);
    EXPECT_TRUE(
        std::equal(storedExact.begin(), storedExact.end(), viewExact.begin(), viewExact.end()));
    for (std::uint64_t k = 0; k < expected.pointCount(line); ++k) {
      const glm::dvec3 p = joinPosition(expected.positions[expected.firstPoint(line) + k],
                                        expected.positionsLow[expected.firstPoint(line) + k]);
      EXPECT_EQ(glm::dvec3(storedExact[3 * k], storedExact[3 * k + 1], storedExact[3 * k + 2]), p);
    }
  }
  // The points of line 0 differ though their float32 positions are the same.
  EXPECT_EQ(expected.positions[0], expected.positions[1]);
  EXPECT_NE(joinPosition(expected.positions[0], expected.positionsLow[0]),
            joinPosition(expected.positions[1], expected.positionsLow[1]));
}

TEST(TraceAccumulator, RoundsWithoutLowPartsGiveTracesWithoutThem) {
  expectSamePoints(accumulated(false).assemble(), byHand(false));
  const StoredTraces stored = accumulated(false).store();
  EXPECT_FALSE(stored.lines().precisePositions);
  std::vector<float> scratch;
  EXPECT_TRUE(stored.column(PointColumn::PositionsLow, 1, scratch).empty());
  std::vector<double> exact;
  const std::span<const double> p = exactPositions(stored, 1, exact);
  ASSERT_EQ(p.size(), 12u);
  EXPECT_EQ(p[3], double(byHand(false).positions[4].x));
}

TEST(TraceAccumulator, EveryRoundWithPointsMustAgreeOnLowParts) {
  std::vector<std::uint32_t> next(kLines, 0);
  TraceAccumulator precise = accumulatorFor(byHand(false));
  precise.add(roundOf({{0, 1}}, next, true));
  EXPECT_THROW(precise.add(roundOf({{0, 1}}, next, false)), std::invalid_argument);

  TraceAccumulator plain = accumulatorFor(byHand(false));
  plain.add(roundOf({{0, 1}}, next, false));
  EXPECT_THROW(plain.add(roundOf({{0, 1}}, next, true)), std::invalid_argument);

  TraceAccumulator refused = accumulatorFor(byHand(false));
  RoundBlock missingOne = roundOf({{0, 2}}, next, true);
  missingOne.positionsLow.pop_back();
  EXPECT_THROW(refused.add(std::move(missingOne)), std::invalid_argument);
  EXPECT_NO_THROW(refused.add(roundOf({{0, 1}}, next, false))) << "a refused round decides nothing";
}

TEST(TraceAccumulator, ARoundWithoutPointsDecidesNothing) {
  std::vector<std::uint32_t> next(kLines, 0);
  TraceAccumulator accumulator = accumulatorFor(byHand(false));
  accumulator.add(roundOf({{0, 0}}, next, false));
  accumulator.add(roundOf({{0, 2}}, next, true));
  EXPECT_TRUE(accumulator.assemble().precisePositions);
}

TEST(TraceAccumulator, APreciseShapeNeedsLowPartsFromTheFirstRound) {
  std::vector<std::uint32_t> next(kLines, 0);
  TraceAccumulator accumulator = accumulatorFor(byHand(true));
  EXPECT_THROW(accumulator.add(roundOf({{0, 1}}, next, false)), std::invalid_argument);
  EXPECT_TRUE(accumulatorFor(byHand(true)).assemble().precisePositions);
}

TEST(TraceAccumulator, LowPartsCountAgainstTheMemoryLimit) {
  EXPECT_EQ(TraceSet::bytesPerPoint(2, true, true) - TraceSet::bytesPerPoint(2, true),
            sizeof(glm::vec3));
  std::vector<std::uint32_t> next(kLines, 0);
  const std::uint64_t limit = kLines * kHeldBytesPerLine + 4 * TraceSet::bytesPerPoint(1, false);
  TraceAccumulator plain = accumulatorFor(byHand(false));
  plain.setMemoryLimit(limit);
  EXPECT_NO_THROW(plain.add(roundOf({{0, 4}}, next, false)));
  TraceAccumulator precise = accumulatorFor(byHand(false));
  precise.setMemoryLimit(limit);
  EXPECT_THROW(precise.add(roundOf({{0, 4}}, next, true)), InputError);
}

TEST(TraceAccumulator, TheLinesCountAgainstTheMemoryLimit) {
  std::vector<std::uint32_t> next(kLines, 0);
  TraceAccumulator accumulator = accumulatorFor(byHand(false));
  accumulator.setMemoryLimit(kLines * kHeldBytesPerLine);
  EXPECT_THROW(accumulator.add(roundOf({{0, 1}}, next, false)), InputError);
}

}  // namespace
}  // namespace amrstream::flow
