// `amrstream bench` end to end on every backend the device has (lavapipe in CI), with validation
// on: rows for each backend, mode and count, GPU step totals equal to the CPU reference's, kernel
// times within the wall times, and history rows over the point budget skipped with a note.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "run_amrstream.hpp"
#include "temp_dir_test.hpp"

namespace {

using ::testing::HasSubstr;

class Bench : public amrstream::testing::TempDirTest {};

TEST_F(Bench, EveryBackendMatchesTheCpuStepsAndReportsItsTimes) {
  const std::string json = (dir_ / "bench.json").string();
  const amrstream::testing::Outcome r = amrstream::testing::runAmrstream(
      "bench builtin:rotation --levels 3 --root-blocks 2 --target-cells 20000 --particles 16,64 "
      "--steps 50 --history-points 2000 --json " +
          json,
      "AMRSTREAM_VALIDATION=1");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("backend   mode      particles"));

  nlohmann::json doc;
  std::ifstream(json) >> doc;
  std::map<std::tuple<std::string, std::string, int>, nlohmann::json> rows;
  for (const auto& row : doc["rows"])
    rows[{row["backend"], row["mode"], row["particles"].get<int>()}] = row;

  // 16 particles x 51 points fit the history budget of 2000 points; 64 x 51 do not.
  for (const std::string backend : {"cpu", "rayquery", "pipeline", "compute"}) {
    SCOPED_TRACE(backend);
    ASSERT_TRUE(rows.count({backend, "endpoints", 16}) && rows.count({backend, "endpoints", 64}) &&
                rows.count({backend, "history", 16}))
        << "lavapipe has all three GPU backends";
    EXPECT_FALSE(rows.count({backend, "history", 64}));
    EXPECT_THAT(doc["notes"].dump(), HasSubstr(backend + " skips history rows from 64 particles"));
  }
  for (const auto& [key, row] : rows) {
    const auto& [backend, mode, particles] = key;
    SCOPED_TRACE(backend + " " + mode + " " + std::to_string(particles));
    const nlohmann::json& cpu = rows.at({"cpu", mode, particles});
    EXPECT_NEAR(row["steps"].get<double>(), cpu["steps"].get<double>(), 2.0);
    EXPECT_GT(row["steps"].get<int>(), particles * 10) << "traces should run for many steps";
    const double wall = row["wall_seconds"];
    if (backend == "cpu") {
      EXPECT_TRUE(row["kernel_seconds"].is_null());
      continue;
    }
    const double kernel = row["kernel_seconds"];
    EXPECT_GT(kernel, 0.0);
    EXPECT_LE(kernel, wall);
    EXPECT_DOUBLE_EQ(row["steps_per_second"].get<double>(), row["steps"].get<double>() / kernel);
    EXPECT_GT(row["device_bytes"].get<double>(), 0.0);
  }
  EXPECT_THAT(doc["notes"].dump(), ::testing::Not(HasSubstr("differ")));
  EXPECT_EQ(doc["setups"].size(), 3u);
}

}  // namespace
