// The writer's point data beyond positions and time: channels, vorticity with vtkStreamTracer's
// Rotation and AngularVelocity, lines of both directions, and periodic lines split or unwrapped.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "output/vtp_writer.hpp"
#include "sample_traces.hpp"
#include "vtp_test_reader.hpp"

namespace amrstream::testing {
namespace {

namespace fs = std::filesystem;

class VtpWriterFields : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("amrstream-vtp-fields-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  VtpFile writeAndRead(const flow::TraceSet& traces, const output::VtpWriteOptions& options = {}) {
    const fs::path path = dir_ / "traces.vtp";
    output::writeVtp(path, traces, options);
    return readVtp(path);
  }

  fs::path dir_;
};

// Line 0: seed 0 forward, 3 points; line 1: seed 0 backward, 1 point; line 2: seed 1 backward,
// 2 points. Channels "dens" = 10 i and "temp" = -i at point i; vorticity (0, 0, i + 1).
flow::TraceSet withPointData() {
  flow::TraceSet t;
  t.vectorName = "vel";
  t.channelNames = {"dens", "temp"};
  t.withVorticity = true;
  t.seedIds = {0, 0, 1};
  t.directions = {1.0f, -1.0f, -1.0f};
  t.steps = {2, 0, 1};
  t.reasons = {AMRSTREAM_REASON_MAX_STEPS, AMRSTREAM_REASON_OUT_OF_DOMAIN,
               AMRSTREAM_REASON_MAX_TIME};
  t.offsets = {0, 3, 4, 6};
  t.times = {0.0f, 0.5f, 1.5f, 0.0f, 0.0f, -0.25f};
  for (int i = 0; i < 6; ++i) {
    t.positions.push_back({float(i), 0.0f, 0.0f});
    t.vectors.push_back({3.0f, 0.0f, 4.0f});  // speed 5
    t.channels.push_back(10.0f * i);
    t.channels.push_back(-float(i));
    t.vorticity.push_back({0.0f, 0.0f, float(i + 1)});
  }
  return t;
}

TEST_F(VtpWriterFields, WritesChannelsAndVtkStreamTracersVorticityArrays) {
  const VtpFile vtp = writeAndRead(withPointData());
  // Written points: 3 + 2 (the 1-point line twice) + 2; their source points:
  const std::vector<int> source{0, 1, 2, 3, 3, 4, 5};
  const auto dens = vtp.array("PointData", "dens").values<float>();
  const auto temp = vtp.array("PointData", "temp").values<float>();
  const auto vorticity = vtp.array("PointData", "Vorticity").values<glm::vec3>();
  const auto angular = vtp.array("PointData", "AngularVelocity").values<float>();
  const auto rotation = vtp.array("PointData", "Rotation").values<float>();
  ASSERT_EQ(dens.size(), source.size());
  for (std::size_t i = 0; i < source.size(); ++i) {
    EXPECT_EQ(dens[i], 10.0f * source[i]);
    EXPECT_EQ(temp[i], -float(source[i]));
    EXPECT_EQ(vorticity[i], glm::vec3(0.0f, 0.0f, float(source[i] + 1)));
    // The vorticity along the unit tangent (3, 0, 4) / 5.
    EXPECT_FLOAT_EQ(angular[i], 0.8f * float(source[i] + 1));
  }
  // Rotation integrates AngularVelocity over IntegrationTime by the trapezoid rule, per line:
  // line 0: 0, (0.8 + 1.6) / 2 * 0.5, + (1.6 + 2.4) / 2 * 1.0.
  EXPECT_FLOAT_EQ(rotation[0], 0.0f);
  EXPECT_FLOAT_EQ(rotation[1], 0.6f);
  EXPECT_FLOAT_EQ(rotation[2], 2.6f);
  EXPECT_EQ(rotation[3], 0.0f);
  EXPECT_EQ(rotation[4], 0.0f);
  // Line 2 runs backward: (4.0 + 4.8) / 2 * -0.25.
  EXPECT_EQ(rotation[5], 0.0f);
  EXPECT_FLOAT_EQ(rotation[6], -1.1f);
  EXPECT_EQ(vtp.array("CellData", "SeedIds").values<std::int32_t>(),
            (std::vector<std::int32_t>{0, 0, 1}));
  EXPECT_EQ(vtp.array("CellData", "ReasonForTermination").values<std::int32_t>(),
            (std::vector<std::int32_t>{5, 1, 7}));
  std::vector<std::string> names;
  for (const VtpArray& array : vtp.arrays)
    if (array.section == "PointData") names.push_back(array.name());
  EXPECT_EQ(names, (std::vector<std::string>{"vel", "dens", "temp", "IntegrationTime", "Vorticity",
                                             "Rotation", "AngularVelocity", "Speed"}));
}

TEST_F(VtpWriterFields, AChannelNamedLikeOurArraysGetsASuffix) {
  flow::TraceSet t = withPointData();
  t.channelNames = {"Speed", "IntegrationTime"};
  const VtpFile vtp = writeAndRead(t);
  EXPECT_EQ(vtp.array("PointData", "Speed_channel").values<float>()[1], 10.0f);
  EXPECT_EQ(vtp.array("PointData", "IntegrationTime_channel").values<float>()[1], -1.0f);
  EXPECT_EQ(vtp.array("PointData", "Speed").values<float>()[1], 5.0f);
}

// One line in a box periodic along x, [0, 1): it wraps between its 2nd and 3rd point and
// between its 4th and 5th.
flow::TraceSet wrappingLine() {
  flow::TraceSet t;
  t.vectorName = "v";
  t.periodic = {{true, false, false}, glm::dvec3(0.0), glm::dvec3(1.0)};
  t.seedIds = {3};
  t.directions = {1.0f};
  t.steps = {4};
  t.reasons = {AMRSTREAM_REASON_MAX_STEPS};
  const float xs[] = {0.8f, 0.9f, 0.05f, 0.15f, 0.95f};
  t.offsets = {0, 5};
  for (int i = 0; i < 5; ++i) {
    t.positions.push_back({xs[i], 0.5f, 0.5f});
    t.times.push_back(0.1f * i);
    t.vectors.push_back({i == 4 ? -1.0f : 1.0f, 0.0f, 0.0f});
  }
  return t;
}

TEST_F(VtpWriterFields, PeriodicLinesAreSplitWhereTheyWrap) {
  const VtpFile vtp = writeAndRead(wrappingLine());
  EXPECT_EQ(vtp.piece.at("NumberOfLines"), "3");
  // Pieces of 2, 2 and 1 points; the last is written twice.
  EXPECT_EQ(vtp.array("Lines", "offsets").values<std::int64_t>(),
            (std::vector<std::int64_t>{2, 4, 6}));
  EXPECT_EQ(vtp.array("CellData", "SeedIds").values<std::int32_t>(),
            (std::vector<std::int32_t>{3, 3, 3}));
  EXPECT_EQ(
      vtp.array("CellData", "ReasonForTermination").values<std::int32_t>(),
      (std::vector<std::int32_t>{AMRSTREAM_REASON_PERIODIC_WRAP, AMRSTREAM_REASON_PERIODIC_WRAP,
                                 AMRSTREAM_REASON_MAX_STEPS}));
  const auto points = vtp.array("Points", "Points").values<glm::vec3>();
  EXPECT_EQ(points[2].x, 0.05f);
  EXPECT_EQ(points[4].x, 0.95f);
  EXPECT_EQ(points[5].x, 0.95f);
}

TEST_F(VtpWriterFields, UnwrappedPeriodicLinesContinuePastTheFaces) {
  output::VtpWriteOptions options;
  options.periodicLines = output::PeriodicLines::Unwrapped;
  const VtpFile vtp = writeAndRead(wrappingLine(), options);
  EXPECT_EQ(vtp.piece.at("NumberOfLines"), "1");
  const auto points = vtp.array("Points", "Points").values<glm::vec3>();
  const float expected[] = {0.8f, 0.9f, 1.05f, 1.15f, 0.95f};
  ASSERT_EQ(points.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_FLOAT_EQ(points[i].x, expected[i]) << "point " << i;
}

// wrappingLine() with precise positions: each point moved along x by (i + 1) 1e-10, which float32
// cannot hold.
flow::TraceSet preciseWrappingLine() {
  flow::TraceSet t = wrappingLine();
  t.precisePositions = true;
  t.positionsLow.resize(t.positions.size());
  for (std::size_t i = 0; i < t.positions.size(); ++i) {
    const flow::SplitPosition split =
        flow::splitPosition(glm::dvec3(t.positions[i]) + glm::dvec3(1e-10 * double(i + 1), 0, 0));
    t.positions[i] = split.high;
    t.positionsLow[i] = split.low;
  }
  return t;
}

TEST_F(VtpWriterFields, PreciseLinesAreSplitAtTheSameWrapsWithFloat64Pieces) {
  const flow::TraceSet t = preciseWrappingLine();
  const VtpFile vtp = writeAndRead(t);
  EXPECT_EQ(vtp.array("Lines", "offsets").values<std::int64_t>(),
            (std::vector<std::int64_t>{2, 4, 6}));
  const VtpArray& points = vtp.array("Points", "Points");
  EXPECT_EQ(points.type(), "Float64");
  const auto values = points.values<glm::dvec3>();
  const std::size_t source[] = {0, 1, 2, 3, 4, 4};
  ASSERT_EQ(values.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i)
    EXPECT_EQ(values[i], exactPosition(t, source[i])) << "written point " << i;
}

TEST_F(VtpWriterFields, UnwrappedPreciseLinesContinuePastTheFacesInFloat64) {
  const flow::TraceSet t = preciseWrappingLine();
  output::VtpWriteOptions options;
  options.periodicLines = output::PeriodicLines::Unwrapped;
  const VtpFile vtp = writeAndRead(t, options);
  const VtpArray& points = vtp.array("Points", "Points");
  EXPECT_EQ(points.type(), "Float64");
  const auto values = points.values<glm::dvec3>();
  const double shift[] = {0.0, 0.0, 1.0, 1.0, 0.0};
  ASSERT_EQ(values.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(values[i].x, exactPosition(t, i).x + shift[i]) << "point " << i;
    EXPECT_EQ(values[i].y, exactPosition(t, i).y) << "point " << i;
  }
}

}  // namespace
}  // namespace amrstream::testing
