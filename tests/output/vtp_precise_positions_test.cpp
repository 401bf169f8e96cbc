// Precise positions (TraceSet::precisePositions) through the .vtp writer and reader: Float64
// <Points> holding the joined positions, read back into the same two parts, in every compression.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "every_compression.hpp"
#include "output/vtp_reader.hpp"
#include "output/vtp_writer.hpp"
#include "sample_traces.hpp"
#include "vtp_test_reader.hpp"

namespace amrstream::testing {
namespace {

namespace fs = std::filesystem;

class VtpPrecisePositions : public ::testing::TestWithParam<output::Compression> {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info->name();
    std::replace(name.begin(), name.end(), '/', '-');
    dir_ = fs::temp_directory_path() /
           ("amrstream-vtp-precise-" + std::to_string(::getpid()) + "-" + name);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const flow::TraceSet& traces) {
    const fs::path path = dir_ / "traces.vtp";
    output::VtpWriteOptions options;
    options.compression = GetParam();
    output::writeVtp(path, traces, options);
    return path;
  }

  fs::path dir_;
};

// Many lines, so that <Points> spans many compressed blocks and more than one batch of them.
std::vector<std::uint32_t> manyPointCounts() {
  std::vector<std::uint32_t> counts;
  for (std::uint32_t seed = 0; seed < 7000; ++seed) counts.push_back(1 + (seed * 37) % 120);
  return counts;
}

// A 1-point trace is written as its point twice.
std::vector<glm::dvec3> writtenPositions(const flow::TraceSet& traces) {
  std::vector<glm::dvec3> written;
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    for (std::uint64_t p = 0; p < traces.pointCount(line); ++p)
      written.push_back(exactPosition(traces, at(traces, line, p)));
    if (traces.pointCount(line) == 1) written.push_back(written.back());
  }
  return written;
}

TEST(PrecisePosition, SplitKeepsWhatFloatLosesAndJoinsBackExactly) {
  const glm::dvec3 a = precisePosition(0, 0), b = precisePosition(0, 1);
  const flow::SplitPosition splitA = flow::splitPosition(a), splitB = flow::splitPosition(b);
  EXPECT_EQ(splitA.high, splitB.high) << "float32 alone cannot tell these points apart";
  const glm::dvec3 joinedA = flow::joinPosition(splitA.high, splitA.low);
  const glm::dvec3 joinedB = flow::joinPosition(splitB.high, splitB.low);
  EXPECT_NE(joinedA, joinedB);
  EXPECT_NEAR(joinedB.x - joinedA.x, 1e-9, 1e-14);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(joinedA[axis], a[axis], 1e-15);
  const flow::SplitPosition again = flow::splitPosition(joinedA);
  EXPECT_EQ(flow::joinPosition(again.high, again.low), joinedA);
}

TEST_P(VtpPrecisePositions, PointsAreFloat64HoldingTheJoinedPositions) {
  const flow::TraceSet traces = preciseSampleTraces(manyPointCounts());
  const VtpFile vtp = readVtp(write(traces));
  const VtpArray& points = vtp.array("Points", "Points");
  EXPECT_EQ(points.type(), "Float64");
  EXPECT_EQ(vtp.array("PointData", "IntegrationTime").type(), "Float32");
  const std::vector<glm::dvec3> expected = writtenPositions(traces);
  const std::vector<glm::dvec3> values = points.values<glm::dvec3>();
  ASSERT_EQ(values.size(), expected.size());
  for (std::size_t i = 0; i < values.size(); ++i)
    ASSERT_EQ(values[i], expected[i]) << "written point " << i;
}

TEST_P(VtpPrecisePositions, ReadsFloat64PointsBackBitForBit) {
  const flow::TraceSet written = preciseSampleTraces(manyPointCounts());
  const flow::TraceSet read = output::readVtpTraces(write(written));
  ASSERT_TRUE(read.precisePositions);
  ASSERT_EQ(pointCountsOf(read), pointCountsOf(written));
  ASSERT_EQ(read.positionsLow.size(), read.pointCount());
  for (std::uint32_t line = 0; line < read.lineCount(); ++line)
    for (std::uint32_t p = 0; p < read.pointCount(line); ++p) {
      const std::uint64_t i = at(read, line, p);
      ASSERT_EQ(exactPosition(read, i), exactPosition(written, i)) << "point " << i;
      ASSERT_EQ(read.positions[i], written.positions[i]) << "point " << i;
      ASSERT_EQ(read.times[i], written.times[i]) << "point " << i;
      ASSERT_NEAR(exactPosition(read, i).x, precisePosition(line, p).x, 1e-15) << "point " << i;
    }
}

TEST_P(VtpPrecisePositions, TracesWithoutPrecisePositionsStayFloat32) {
  const flow::TraceSet written = sampleTraces(kSamplePointCounts);
  const fs::path path = write(written);
  EXPECT_EQ(readVtp(path).array("Points", "Points").type(), "Float32");
  const flow::TraceSet read = output::readVtpTraces(path);
  EXPECT_FALSE(read.precisePositions);
  EXPECT_TRUE(read.positionsLow.empty());
  EXPECT_EQ(read.positions, written.positions);
}

TEST_P(VtpPrecisePositions, AnEmptyPreciseTraceSetIsAFloat64FileAndComesBackPrecise) {
  const fs::path path = write(preciseSampleTraces({}));
  EXPECT_EQ(readVtp(path).array("Points", "Points").type(), "Float64");
  const flow::TraceSet read = output::readVtpTraces(path);
  EXPECT_TRUE(read.precisePositions);
  EXPECT_EQ(read.pointCount(), 0u);
}

TEST_P(VtpPrecisePositions, MissingLowPartsAreInconsistentTraces) {
  flow::TraceSet traces = preciseSampleTraces(kSamplePointCounts);
  traces.positionsLow.pop_back();
  EXPECT_THROW(write(traces), std::invalid_argument);
  traces = sampleTraces(kSamplePointCounts);
  traces.positionsLow.resize(traces.pointCount());  // low parts without precisePositions
  EXPECT_THROW(write(traces), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(EveryCompression, VtpPrecisePositions, kEveryCompression,
                         compressionTestName);

}  // namespace
}  // namespace amrstream::testing
