// `trace --json` accounts for the whole command: its stages add up to the wall time the test
// measures around the process, each stage the summary times appears with its time, and the
// counts are those of the .vtp written. Bad uses of --json are refused before any work.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "run_amrstream.hpp"
#include "temp_dir_test.hpp"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

class TraceJson : public amrstream::testing::TempDirTest {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
};

TEST_F(TraceJson, TheStagesAddUpToTheWholeCommand) {
  const auto start = std::chrono::steady_clock::now();
  const amrstream::testing::Outcome r = amrstream::testing::runAmrstream(
      "trace builtin:cloud --levels 4 --root-blocks 4 --target-cells 300000 --count 2000 "
      "--backend cpu --out " +
      path("t.vtp") + " --json " + path("t.json"));
  const double measured =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream in(path("t.json"));
  const nlohmann::json doc = nlohmann::json::parse(in);

  std::map<std::string, double> stages;
  double sum = 0.0;
  for (const auto& stage : doc.at("stages")) {
    stages[stage.at("name")] = stage.at("seconds");
    sum += stage.at("seconds").get<double>();
    EXPECT_GE(stage.at("seconds").get<double>(), 0.0) << stage.at("name");
  }
  const double wall = doc.at("wall_seconds");
  EXPECT_NEAR(sum, wall, 1e-9);
  // The process runs a little longer than its clock (the shell, the exit), whose start is known
  // to a clock tick (10 ms).
  EXPECT_LE(wall, measured + 0.011);
  EXPECT_GE(wall, 0.9 * measured - 0.05) << "the stages miss part of the command: " << r.output;
  for (const char* name : {"start", "cell checks", "overlap check", "input", "bricks", "regions",
                           "seeds", "tracing", "output"})
    EXPECT_TRUE(stages.contains(name)) << name;
  EXPECT_GE(stages["tracing"], doc.at("trace_seconds").get<double>());

  EXPECT_EQ(doc.at("backend"), "cpu");
  EXPECT_EQ(doc.at("seeds"), 2000);
  EXPECT_EQ(doc.at("lines"), 4000);  // both directions
  EXPECT_GT(doc.at("steps").get<double>(), 4000.0);
  EXPECT_THAT(r.output, HasSubstr("(4,000 polylines, "));
  EXPECT_THAT(r.output, HasSubstr("\nwall       "));
}

// On a GPU backend the device setup's parts are there, the device opened while the input was
// read; lavapipe is a CPU device, whose kernels read compact values, not dual cells.
TEST_F(TraceJson, AGpuBackendsDeviceSetup) {
  const amrstream::testing::Outcome r = amrstream::testing::runAmrstream(
      "trace builtin:rotation --count 64 --backend compute --out " + path("t.vtp") + " --json " +
      path("t.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream in(path("t.json"));
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc.at("backend"), "compute");
  const nlohmann::json& setup = doc.at("device_setup");
  EXPECT_EQ(setup.at("dual_cells"), false);
  EXPECT_GE(setup.at("seconds").get<double>(), setup.at("upload_seconds").get<double>() +
                                                   setup.at("structure_seconds").get<double>() +
                                                   setup.at("kernel_seconds").get<double>());
  EXPECT_THAT(r.output, Not(HasSubstr("with dual cells")));
}

TEST_F(TraceJson, OnlyAJsonFileAndOneProcessAreAccepted) {
  auto r = amrstream::testing::runAmrstream("trace builtin:rotation --count 4 --out " +
                                            path("t.vtp") + " --json " + path("t.txt"));
  EXPECT_NE(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("--json"));
  r = amrstream::testing::runAmrstream("trace builtin:rotation --count 4 --pieces --out " +
                                       path("t.pvtp") + " --json " + path("t.json"));
  EXPECT_NE(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("in one process"));
  EXPECT_FALSE(fs::exists(path("t.json")));
}

}  // namespace
