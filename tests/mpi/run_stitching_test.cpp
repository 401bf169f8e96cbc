// Runs of lines traced over data: routed to the rank whose piece holds their line (contiguous
// ranges that tile the lines), and stitched there into whole lines of that range.

#include "mpi/run_stitching.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "../../shaders/glsl/shared/trace_codes.h"

namespace amrstream::mpi {
namespace {

// A run of line `line` ending after `steps` steps, `points` points encoding (line, steps, k).
void addRun(flow::TraceSet& t, std::uint32_t line, std::uint32_t steps, std::uint32_t points,
            bool ends) {
  t.seedIds.push_back(line);
  t.directions.push_back(0.0f);
  t.steps.push_back(steps);
  t.reasons.push_back(ends ? AMRSTREAM_REASON_MAX_STEPS : AMRSTREAM_REASON_RUNNING);
  for (std::uint32_t k = 0; k < points; ++k) {
    t.positions.push_back(glm::vec3(float(line), float(steps), float(k)));
    t.times.push_back(float(k));
    t.vectors.push_back(glm::vec3(1.0f));
  }
  t.offsets.push_back(t.offsets.back() + points);
}

TEST(PieceLines, TileTheLinesInRankOrder) {
  for (const std::size_t lines : {0u, 1u, 2u, 7u, 100u, 1001u})
    for (const int ranks : {1, 2, 3, 5, 8}) {
      std::uint32_t next = 0;
      for (int rank = 0; rank < ranks; ++rank) {
        const LineRange range = pieceLines(lines, rank, ranks);
        EXPECT_EQ(range.first, next);
        EXPECT_LE(range.last - range.first, lines / std::size_t(ranks) + 1);
        next = range.last;
      }
      EXPECT_EQ(next, lines);
    }
}

TEST(RunsByPiece, SendEachRunToTheRankWritingItsLineAndStitchThere) {
  constexpr std::size_t kLines = 10;
  constexpr int kRanks = 3;
  flow::TraceSet runs;
  // Each line in two runs, the later one first.
  for (std::uint32_t line = 0; line < kLines; ++line) addRun(runs, line, 8, 4, true);
  for (std::uint32_t line = 0; line < kLines; ++line) addRun(runs, line, 5, 6, false);
  const std::vector<flow::TraceSet> pieces = runsByPiece(runs, kLines, kRanks);
  ASSERT_EQ(pieces.size(), std::size_t(kRanks));
  flow::LineLayout layout;
  for (std::uint32_t line = 0; line < kLines; ++line) {
    layout.seedIds.push_back(100 + line);
    layout.directions.push_back(1.0f);
  }
  for (int rank = 0; rank < kRanks; ++rank) {
    const LineRange range = pieceLines(kLines, rank, kRanks);
    const flow::TraceSet& piece = pieces[std::size_t(rank)];
    EXPECT_EQ(piece.lineCount(), 2 * (range.last - range.first));
    for (const std::uint32_t line : piece.seedIds) {
      EXPECT_GE(line, range.first);
      EXPECT_LT(line, range.last);
    }
    const flow::TraceSet lines = stitchRuns({piece}, layout, range);
    ASSERT_EQ(lines.lineCount(), range.last - range.first);
    for (std::size_t i = 0; i < lines.lineCount(); ++i) {
      EXPECT_EQ(lines.seedIds[i], 100 + range.first + i);
      EXPECT_EQ(lines.steps[i], 8u);
      ASSERT_EQ(lines.pointCount(i), 10u);
      // The run of 5 steps first, then the one of 8.
      EXPECT_EQ(lines.positions[lines.firstPoint(i)].y, 5.0f);
      EXPECT_EQ(lines.positions[lines.firstPoint(i) + 6].y, 8.0f);
      EXPECT_EQ(lines.positions[lines.firstPoint(i)].x, float(range.first + i));
    }
    // A piece's runs do not make the lines of another range.
    if (rank > 0) {
      EXPECT_THROW(stitchRuns({piece}, layout, pieceLines(kLines, 0, kRanks)), std::runtime_error);
    }
  }
}

}  // namespace
}  // namespace amrstream::mpi
