// The library through its front door alone: this file is compiled with include/ as its only
// project include path (tests/api/CMakeLists.txt), so every name it uses is public. Oracles: a
// uniform field moves a seed by h cell widths a step along the field; solid-body rotation keeps a
// seed's distance from its axis; a written .vtp reads back as the lines that were traced.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "amrstream/builtin.hpp"
#include "amrstream/closest_name.hpp"
#include "amrstream/dataset.hpp"
#include "amrstream/distributed.hpp"
#include "amrstream/error.hpp"
#include "amrstream/field.hpp"
#include "amrstream/rendering.hpp"
#include "amrstream/run_files.hpp"
#include "amrstream/trace_job.hpp"
#include "amrstream/tracing.hpp"
#include "amrstream/version.hpp"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// 16^3 cells of one level over the unit cube, the vector (1, 0, 0) everywhere.
amrstream::Dataset uniformFlow() {
  amrstream::CellArrays cells;
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        cells.corners.push_back({x, y, z});
        cells.levels.push_back(0);
      }
  const std::size_t n = cells.corners.size();
  cells.channels = {{"velx", std::vector<float>(n, 1.0f)},
                    {"vely", std::vector<float>(n, 0.0f)},
                    {"velz", std::vector<float>(n, 0.0f)},
                    {"dens", std::vector<float>(n, 2.0f)}};
  cells.finestWidth = glm::dvec3(1.0 / 16.0);
  cells.source = "uniform";
  return amrstream::fromCells(std::move(cells));
}

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("amrstream_api_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

TEST(FrontDoor, AUniformFieldMovesASeedByTheStepAlongIt) {
  const amrstream::Dataset dataset = uniformFlow();
  EXPECT_EQ(dataset.cellCount(), 4096u);
  const amrstream::Field field = amrstream::buildField(dataset, {});
  EXPECT_EQ(field.vectorName(), "vel");
  EXPECT_EQ(field.pointDataNames(), std::vector<std::string>{"dens"});

  amrstream::TraceSettings settings;
  settings.steps = 8;
  settings.direction = "forward";
  amrstream::PreparedJob job = amrstream::prepare(field, {{0.2, 0.5, 0.5}}, settings, {"cpu"});
  const amrstream::Traces traces = amrstream::trace(job).assemble();
  ASSERT_EQ(traces.lineCount(), 1u);
  ASSERT_EQ(traces.pointCount(), 9u);  // the seed and 8 steps of 0.25 cell widths
  for (std::uint64_t i = 0; i < traces.pointCount(); ++i) {
    const glm::dvec3 p = traces.point(i);
    EXPECT_NEAR(p.x, 0.2 + double(i) * 0.25 / 16.0, 1e-6) << "point " << i;
    EXPECT_NEAR(p.y, 0.5, 1e-6);
    EXPECT_NEAR(p.z, 0.5, 1e-6);
  }
  const std::vector<float> dens = traces.pointData("dens");
  EXPECT_THAT(dens, ::testing::Each(::testing::FloatNear(2.0f, 1e-6f)));
  EXPECT_EQ(traces.reasons()[0], 5);  // max steps
  EXPECT_EQ(traces.report().backend, "cpu");
}

TEST(FrontDoor, SolidBodyRotationKeepsTheRadiusAndTheFileReadsBack) {
  TempDir dir;
  amrstream::TraceJob job;
  job.dataset = {"builtin:rotation", {2, 2, 20000, 1, 0.0}};
  job.seeds.line = {0.3, 0.5, 0.5, 0.45, 0.5, 0.5};
  job.seeds.count = 4;
  job.trace.steps = 200;
  job.backend.backend = "cpu";
  std::vector<std::string> lines;
  const amrstream::Reporter reporter{[&](const std::string& line) { lines.push_back(line); }, {}};
  amrstream::PreparedJob prepared = amrstream::prepare(job, {}, reporter);
  EXPECT_EQ(prepared.seeds().size(), 4u);
  const amrstream::TracedLines traced = amrstream::trace(prepared, {}, reporter);
  const amrstream::WrittenLines written = traced.write({dir.file("rotation.vtp")}, reporter.log);
  EXPECT_EQ(written.lines, 8u);  // both directions

  const amrstream::Traces back = amrstream::readTraces(dir.file("rotation.vtp"));
  ASSERT_EQ(back.lineCount(), 8u);
  EXPECT_EQ(back.pointCount(), written.points);
  for (std::size_t line = 0; line < back.lineCount(); ++line) {
    const std::uint64_t first = back.offsets()[line], end = back.offsets()[line + 1];
    const glm::dvec3 seed = back.point(first);
    const double radius = glm::length(glm::dvec2(seed.x - 0.5, seed.y - 0.5));
    for (std::uint64_t i = first; i < end; ++i) {
      const glm::dvec3 p = back.point(i);
      EXPECT_NEAR(glm::length(glm::dvec2(p.x - 0.5, p.y - 0.5)), radius, 1e-3)
          << "line " << line << " point " << i - first;
    }
  }
  const auto said = [&](const std::string& start) {
    return std::count_if(lines.begin(), lines.end(),
                         [&](const std::string& l) { return l.starts_with(start); });
  };
  for (const char* start :
       {"input ", "structure ", "seeds ", "stepping ", "steps ", "reasons ", "time ", "output "})
    EXPECT_EQ(said(start), 1) << start;
}

TEST(FrontDoor, TheWholeJobWritesTheFileOneProcessOrAWorldOfOneWould) {
  TempDir dir;
  amrstream::TraceJob job;
  job.dataset = {"builtin:abc", {2, 2, 20000, 1, 0.0}};
  job.seeds.count = 8;
  job.trace.steps = 50;
  job.backend.backend = "cpu";
  amrstream::runTraceJob(job, {dir.file("one.vtp")}, amrstream::TraceStore::Auto);
  const amrstream::MpiWorld world;  // not started by mpirun: one rank
  ASSERT_EQ(world.size(), 1);
  amrstream::traceDistributed(world, job, {dir.file("world.vtp")}, {}, [] {});
  const amrstream::Traces one = amrstream::readTraces(dir.file("one.vtp"));
  const amrstream::Traces all = amrstream::readTraces(dir.file("world.vtp"));
  ASSERT_EQ(one.pointCount(), all.pointCount());
  for (std::uint64_t i = 0; i < one.pointCount(); ++i) ASSERT_EQ(one.point(i), all.point(i));
}

TEST(FrontDoor, BadSettingsAndFilesAreInputErrors) {
  const amrstream::Field field = amrstream::buildField(uniformFlow(), {});
  amrstream::TraceSettings settings;
  settings.stepMode = "sideways";
  EXPECT_THROW(amrstream::prepare(field, {{0.5, 0.5, 0.5}}, settings, {"cpu"}),
               amrstream::InputError);
  EXPECT_THROW(amrstream::prepare(field, {{2.0, 0.5, 0.5}}, {}, {"cpu"}), amrstream::InputError);
  EXPECT_THROW(amrstream::buildField(uniformFlow(), {"a,b,c"}), amrstream::InputError);
  EXPECT_THROW(amrstream::load("/nonexistent/file.exa"), amrstream::InputError);

  TempDir dir;
  const std::string input = dir.file("input.txt");
  std::fclose(std::fopen(input.c_str(), "w"));
  amrstream::RunFiles files;
  files.addInput(input);
  try {
    files.addOutput("--out", input);
    FAIL() << "an output over an input was accepted";
  } catch (const amrstream::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--out"));
  }
}

// The renderer turns about the up axis and looks from straight below to straight above: a camera
// past those angles is refused before a device is looked for (it used to be clamped to +-90).
TEST(FrontDoor, CameraAnglesBeyondTheRenderersAreInputErrors) {
  const amrstream::Field field = amrstream::buildField(uniformFlow(), {});
  amrstream::BackendRequest cpu;
  cpu.backend = "cpu";
  amrstream::PreparedJob job = amrstream::prepare(field, {{0.2, 0.5, 0.5}}, {}, cpu);
  const amrstream::Traces traces = amrstream::trace(job).assemble();
  const auto refusal = [&](std::vector<float> camera) {
    amrstream::RenderOptions look;
    look.camera = std::move(camera);
    try {
      amrstream::renderImage(amrstream::BackendRequest{}, look, field, traces);  // auto
    } catch (const amrstream::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal({30.0f, 200.0f}),
            "camera: elevation 200 is outside the range -90 to 90 degrees");
  EXPECT_EQ(refusal({30.0f, -90.5f}),
            "camera: elevation -90.5 is outside the range -90 to 90 degrees");
  EXPECT_EQ(refusal({1e30f, 20.0f}),
            "camera: azimuth 1e+30 is outside the range -360 to 360 degrees");
}

TEST(FrontDoor, ClosestNamesIgnoreCaseAndAFewTypos) {
  const std::vector<std::string> names = {"dens", "magx", "magy", "magz", "--count"};
  EXPECT_EQ(amrstream::closestName("MAGX", names), "magx");
  EXPECT_EQ(amrstream::closestName("Dens", names), "dens");
  EXPECT_EQ(amrstream::closestName("--cout", names), "--count");
  EXPECT_EQ(amrstream::closestName("density", names),
            std::nullopt);  // 3 edits of 7 letters: 2 allowed
  EXPECT_EQ(amrstream::closestName("x", names), std::nullopt);
  EXPECT_EQ(amrstream::didYouMean("mag_x", names), " (did you mean 'magx'?)");
  EXPECT_EQ(amrstream::didYouMean("pressure", names), "");
}

TEST(FrontDoor, TheVersionIsStatedOnce) {
  EXPECT_STREQ(amrstream::kVersion, AMRSTREAM_VERSION);
  const std::string version = amrstream::kVersion;
  EXPECT_EQ(std::count(version.begin(), version.end(), '.'), 2) << version;
}

}  // namespace
