// `amrstream pathlines` end to end: a generated series in any order, streaklines, the real
// Gerris series from its files as they are, and bad series that must fail naming the file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "run_amrstream.hpp"
#include "temp_dir_test.hpp"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
using amrstream::testing::Outcome;

Outcome run(const std::string& arguments) { return amrstream::testing::runAmrstream(arguments); }

class PathlinesCli : public amrstream::testing::TempDirTest {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // swirl_0000.exa ... at times 0, 0.05, ...
  void generateSwirl(int snapshots, const std::string& prefix = "swirl") {
    const Outcome r = run("gen swirl --levels 3 --root-blocks 2 --target-cells 20000 --series " +
                          std::to_string(snapshots) + " --interval 0.05 --out " + path(prefix));
    ASSERT_EQ(r.status, 0) << r.output;
  }
};

TEST_F(PathlinesCli, TracesAGeneratedSeriesGivenInAnyOrder) {
  generateSwirl(5);
  // Named last first: the times in the files set the order.
  const Outcome r = run("pathlines " + path("swirl_0004.exa") + " '" + path("swirl_000[0-3].exa") +
                        "' --count 16 --seed-box 0.3,0.3,0.3,0.7,0.7,0.7 --point-data temp --out " +
                        path("p.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("series     5 snapshots from t = 0 ("));
  EXPECT_THAT(r.output, HasSubstr("to 0.2 ("));
  EXPECT_THAT(r.output, HasSubstr("stepping   dt = 0.005 from t = 0 to 0.2"));
  EXPECT_THAT(r.output, HasSubstr("end of series (9): 16"));
  EXPECT_THAT(r.output, HasSubstr("(16 pathlines, "));
  EXPECT_GT(fs::file_size(path("p.vtp")), 1000u);
}

TEST_F(PathlinesCli, WritesStreaklinesWithReleaseEvery) {
  generateSwirl(3);
  const Outcome r = run("pathlines '" + path("swirl_*.exa") +
                        "' --seed-line 0.6,0.5,0.5,0.7,0.5,0.5 --count 3 --release-every 0.01 "
                        "--end-time 0.08 --out " +
                        path("s.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("released every 0.01"));
  EXPECT_THAT(r.output, HasSubstr("particles  24 (3 seeds)"));
  EXPECT_THAT(r.output, HasSubstr("max time (7): 24"));
  EXPECT_THAT(r.output, HasSubstr("(3 streaklines, 24 points)"));
}

TEST_F(PathlinesCli, DeclaresUnitsForSnapshotsThatStateNone) {
  generateSwirl(3);
  const std::string series = "'" + path("swirl_*.exa") + "' --count 4 --compression none ";
  const Outcome r =
      run("pathlines " + series + "--length-unit km --unit temp=K --out " + path("p.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream file(path("p.vtp"), std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(file), {}};
  EXPECT_THAT(bytes, HasSubstr("Name=\"LengthUnit\""));
  EXPECT_THAT(bytes, HasSubstr(std::string("km\0", 3)));

  const Outcome bad = run("pathlines " + series + "--unit tmp=K --out " + path("q.vtp"));
  EXPECT_NE(bad.status, 0);
  EXPECT_THAT(bad.output, HasSubstr("--unit: 'tmp' is no channel or vector of"));
  EXPECT_THAT(bad.output, HasSubstr("did you mean 'temp'?"));
  EXPECT_FALSE(fs::exists(path("q.vtp")));
}

TEST_F(PathlinesCli, RunsTheRealGerrisSeriesFromItsFiles) {
  const fs::path archive = fs::path(AMRSTREAM_REAL_DATA_DIR) / "gerris-ring-series.tar.xz";
  if (!fs::exists(archive)) GTEST_SKIP() << "the Gerris series is not at " << archive;
  ASSERT_EQ(std::system(("tar -xJf " + archive.string() + " -C " + dir_.string()).c_str()), 0);
  const Outcome r =
      run("pathlines '" + path("gerris-ring-series/ring-*.txt") +
          "' --seed-grid 4,4,2 --seed-box -0.2,-0.2,-0.4,0.2,0.2,-0.1 --end-time 0.3 --out " +
          path("ring.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("series     31 snapshots from t = 0 ("));
  EXPECT_THAT(r.output, HasSubstr("16 snapshots used"));  // 0, 0.02, ..., 0.3
  EXPECT_THAT(r.output, HasSubstr("max time (7): 32"));
}

// 'DD*/name*' matches an Enzo dataset's parameter file and all the files named after it: they
// are one snapshot, so one Enzo output is a series of one.
TEST_F(PathlinesCli, AnEnzoOutputsFilesAreOneSnapshot) {
  const fs::path dd = fs::path(AMRSTREAM_REAL_DATA_DIR) / "enzo-moving7" / "DD0010";
  if (!fs::exists(dd)) GTEST_SKIP() << "the Enzo output is not at " << dd;
  const Outcome r =
      run("pathlines '" + (dd / "moving7_0010*").string() + "' --out " + path("e.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("a series needs two snapshots or more; 1 given"));
}

// A step or a release interval that the run could never finish (more steps than a particle may
// take, more particles than a run may hold, times that double precision cannot tell apart) is
// refused before any snapshot is traced, naming the setting and the figure.
TEST_F(PathlinesCli, RefusesStepsAndReleasesItCouldNeverFinish) {
  generateSwirl(2);
  const std::string series = "pathlines '" + path("swirl_*.exa") + "' --out " + path("x.vtp") + " ";
  const struct {
    std::string options, error;
  } cases[] = {
      {"--count 4 --step-size 1e-12",
       "--step-size: 1e-12 needs 5e+10 steps from t = 0 to 0.05, more than "
       "the 1000000000 a particle may take"},
      {"--count 4 --step-size 1e-30", "--step-size: 1e-30 needs 5e+28 steps"},
      {"--count 4 --release-every 1e-9",
       "--release-every: 1e-09 makes 2e+08 particles of 4 seeds with "
       "about 1.2e+09 points, which need"},
      {"--count 100000 --release-every 1e-6",
       "--release-every: 1e-06 releases the seeds 5e+04 times from t = 0 to 0.05, 5e+09 "
       "particles of 100000 seeds, more than the 2147483647 particles a run may hold"},
      {"--count 4 --release-every 1e-12", "--release-every: 1e-12 releases the seeds 5e+10 times"},
      {"--count 4 --release-every 1e-20", "--release-every: 1e-20 releases the seeds 5e+18 times"},
      {"--count 4 --release-every 1e-30", "--release-every: 1e-30 releases the seeds 5e+28 times"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.options);
    const Outcome r = run(series + c.options);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.error));
    EXPECT_FALSE(fs::exists(path("x.vtp")));
  }
  // Snapshots 1e-10 apart in a series of 1: the default step (a tenth of that) would take 1e10
  // steps, and at t = 1e6 it is below what the times resolve; both name the closest snapshots.
  const std::string gen = "gen swirl --levels 2 --root-blocks 1 --target-cells 600 --out ";
  for (const auto& [name, time] : {std::pair{"near/a", "0"},
                                   {"near/b", "1e-10"},
                                   {"near/c", "1"},
                                   {"far/a", "1e6"},
                                   {"far/b", "1000000.0000000001"}}) {
    fs::create_directories(fs::path(path(name)).parent_path());
    ASSERT_EQ(run(gen + path(name) + " --time " + time).status, 0);
  }
  Outcome r = run("pathlines '" + path("near/*.exa") + "' --count 4 --out " + path("x.vtp"));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--step-size: 1e-11 (the default, a tenth of the shortest "
                                  "interval used) needs 1e+11 steps from t = 0 to 1"));
  EXPECT_THAT(r.output, HasSubstr("near/a.exa and " + path("near/b.exa") + " are closest"));
  r = run("pathlines '" + path("far/*.exa") + "' --count 4 --out " + path("x.vtp"));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("is too small to step by at t = 1e+06, whose double precision "
                                  "cannot resolve it"));
  EXPECT_FALSE(fs::exists(path("x.vtp")));
}

// The field is not known past the last snapshot: an end time after it is refused, not clipped.
TEST_F(PathlinesCli, AnEndTimeAfterTheSeriesIsRefused) {
  generateSwirl(2);
  const Outcome r =
      run("pathlines '" + path("swirl_*.exa") + "' --count 4 --end-time 5 --out " + path("x.vtp"));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--end-time: 5 is after the series, which ends at 0.05 (" +
                                  path("swirl_0001.exa") + ")"));
  EXPECT_FALSE(fs::exists(path("x.vtp")));
}

TEST_F(PathlinesCli, BadSeriesFailNamingTheFile) {
  generateSwirl(2);
  Outcome r = run("pathlines " + path("swirl_0000.exa") + " --out " + path("x.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("a series needs two snapshots or more; 1 given"));

  r = run("pathlines '" + path("nothing_*.exa") + "' --out " + path("x.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("nothing_*.exa: matches no file"));

  // The same time twice.
  ASSERT_EQ(
      run("gen swirl --levels 2 --root-blocks 1 --target-cells 600 --out " + path("again")).status,
      0);
  r = run("pathlines '" + path("swirl_*.exa") + "' " + path("again.exa") + " --out " +
          path("x.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("it is at time 0, as"));

  // A Gerris dump whose header states no time.
  std::ofstream(path("untimed.txt")) << "# 1:x 2:y 3:z 4:U 5:V 6:W 7:Lev\n0.25 0.25 0.25 1 0 0 1\n";
  r = run("pathlines '" + path("swirl_*.exa") + "' " + path("untimed.txt") + " --out " +
          path("x.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("untimed.txt: the file states no time"));

  r = run("pathlines '" + path("swirl_*.exa") + "' --start-time 0.5 --out " + path("x.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("--start-time: 0.5 is outside the series"));

  // A later snapshot without the first one's point data (rotation has no temp).
  ASSERT_EQ(run("gen rotation --levels 2 --root-blocks 1 --target-cells 600 --time 0.07 --out " +
                path("rot"))
                .status,
            0);
  r = run("pathlines '" + path("swirl_*.exa") + "' " + path("rot.exa") + " --out " + path("x.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("rot.exa: its point-data channels are none, the first "
                                  "snapshot's temp"));
  EXPECT_FALSE(fs::exists(path("x.vtp")));
}

}  // namespace
