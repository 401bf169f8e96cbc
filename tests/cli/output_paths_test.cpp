// Outputs that would destroy what a run reads or writes are refused before any work: a file of
// the input dataset (by its path, another spelling, a symbolic or a hard link), a file inside an
// input directory, the seeds file, or another output of the same run. The refused run exits with
// status 2 naming the option and both paths, and leaves every file as it was.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "run_amrstream.hpp"
#include "temp_dir_test.hpp"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
using amrstream::testing::Outcome;

Outcome run(const std::string& arguments) { return amrstream::testing::runAmrstream(arguments); }

const std::string kSmall = " --levels 3 --root-blocks 2 --target-cells 20000";
const fs::path kRealData(AMRSTREAM_REAL_DATA_DIR);

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

class OutputPaths : public amrstream::testing::TempDirTest {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // rot.exa, rot.cells and rot.velx.scalars, ...
  void generate() {
    const Outcome r = run("gen rotation" + kSmall + " --out " + path("rot"));
    ASSERT_EQ(r.status, 0) << r.output;
  }

  // Every file under dir_ with its bytes.
  std::map<fs::path, std::string> snapshot() const {
    std::map<fs::path, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir_))
      if (entry.is_regular_file()) files[entry.path()] = contents(entry.path());
    return files;
  }

  // Runs `arguments` and expects the refusal `message` with status 2, every file as before and
  // none added (no output, no temporary).
  void expectRefused(const std::string& arguments, const std::string& message) {
    const std::map<fs::path, std::string> before = snapshot();
    const Outcome r = run(arguments);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr(message)) << arguments;
    EXPECT_THAT(r.output, ::testing::Not(HasSubstr("input      "))) << "work began: " << arguments;
    EXPECT_TRUE(snapshot() == before) << "files changed: " << arguments;
  }

  // Copies a real dataset (file or directory) into dir_, or skips the test.
  fs::path copyReal(const std::string& relative) {
    const fs::path from = kRealData / relative;
    if (!fs::exists(from)) return {};
    const fs::path to = dir_ / from.filename();
    fs::copy(from, to, fs::copy_options::recursive);
    return to;
  }
};

TEST_F(OutputPaths, TraceRefusesEveryFileOfAnExaInput) {
  generate();
  ASSERT_TRUE(fs::exists(path("rot.velx.scalars")));
  const std::string trace = "trace " + path("rot.exa") + " --backend cpu --count 4 --out ";
  for (const char* name : {"rot.exa", "rot.cells", "rot.velx.scalars"})
    expectRefused(trace + path(name), "--out: '" + path(name) + "' is the input '");
  // Another spelling, a symbolic link and a hard link to input files.
  expectRefused(trace + (dir_ / "." / "rot.exa").string(), "is the input");
  fs::create_symlink(path("rot.cells"), path("link.vtp"));
  expectRefused(trace + path("link.vtp"),
                "--out: '" + path("link.vtp") + "' is the input '" + path("rot.cells") + "'");
  fs::create_hard_link(path("rot.vely.scalars"), path("hard.vtp"));
  expectRefused(trace + path("hard.vtp"), "--out: '" + path("hard.vtp") + "' is the input '" +
                                              path("rot.vely.scalars") + "'");
}

TEST_F(OutputPaths, OutputsOfOneRunMustDiffer) {
  expectRefused(
      "trace builtin:rotation" + kSmall + " --backend cpu --count 4 --seeds-out " + path("t.vtp") +
          " --out " + path("t.vtp"),
      "--out: '" + path("t.vtp") + "' is also the output of --seeds-out ('" + path("t.vtp") + "')");
  expectRefused("trace builtin:rotation" + kSmall + " --backend cpu --count 4 --seeds-out " +
                    path("s.txt") + " --out " + (dir_ / "." / "s.txt").string(),
                "is also the output of --seeds-out");
}

TEST_F(OutputPaths, TheSeedsFileIsAnInput) {
  std::ofstream(path("seeds.txt")) << "0.5 0.5 0.5\n";
  expectRefused("trace builtin:rotation" + kSmall + " --backend cpu --seeds " + path("seeds.txt") +
                    " --seeds-out " + path("seeds.txt") + " --out " + path("t.vtp"),
                "--seeds-out: '" + path("seeds.txt") + "' is the input '" + path("seeds.txt"));
  expectRefused("trace builtin:rotation" + kSmall + " --backend cpu --seeds " + path("seeds.txt") +
                    " --out " + path("seeds.txt"),
                "--out: '" + path("seeds.txt") + "' is the input");
}

// The check comes before the seeds are written: a run refused for --out leaves no seeds file.
TEST_F(OutputPaths, AnOutputWhoseDirectoryIsMissingIsRefusedBeforeTheSeedsAreWritten) {
  expectRefused("trace builtin:rotation" + kSmall + " --backend cpu --count 4 --seeds-out " +
                    path("s.txt") + " --out " + path("no/such/t.vtp"),
                "--out: cannot write '" + path("no/such/t.vtp") + "': the directory '" +
                    path("no/such") + "' does not exist");
  expectRefused(
      "trace builtin:rotation" + kSmall + " --backend cpu --count 4 --out " + dir_.string(),
      "--out: '" + dir_.string() + "' is a directory");
  expectRefused("gen rotation" + kSmall + " --out " + path("no/such/rot"),
                "--out: cannot write '" + path("no/such/rot.exa") + "'");
}

TEST_F(OutputPaths, RenderRefusesToWriteOverItsTracesOrItsInput) {
  generate();
  std::ofstream(path("t.vtp")) << "not read: the outputs are checked first";
  expectRefused(
      "render builtin:rotation" + kSmall + " --traces " + path("t.vtp") + " --out " + path("t.vtp"),
      "--out: '" + path("t.vtp") + "' is the input");
  expectRefused("render " + path("rot.exa") + " --out " + path("rot.velz.scalars"),
                "--out: '" + path("rot.velz.scalars") + "' is the input");
}

TEST_F(OutputPaths, ConvertRefusesToWriteOverItsInput) {
  generate();
  expectRefused("convert " + path("rot.exa") + " " + path("rot.exa"),
                "OUT: '" + path("rot.exa") + "' is the input");
  expectRefused("convert " + path("rot.exa") + " " + path("rot"), "is the input");
  // Only the input's own files are refused.
  ASSERT_EQ(run("convert " + path("rot.exa") + " " + path("copy.exa")).status, 0);
  EXPECT_TRUE(fs::exists(path("copy.velx.scalars")));
}

TEST_F(OutputPaths, PathlinesAndBenchRefuseToWriteOverTheirInputs) {
  const Outcome r =
      run("gen swirl" + kSmall + " --series 3 --interval 0.05 --out " + path("swirl"));
  ASSERT_EQ(r.status, 0) << r.output;
  expectRefused(
      "pathlines '" + path("swirl_*.exa") + "' --count 4 --out " + path("swirl_0001.cells"),
      "--out: '" + path("swirl_0001.cells") + "' is the input");
  // pathlines chooses its seeds inside the run and cannot write them: --seeds-out is no option
  // of it, instead of one silently ignored.
  const Outcome seedsOut = run("pathlines '" + path("swirl_*.exa") + "' --count 4 --seeds-out " +
                               path("s.txt") + " --out " + path("p.vtp"));
  EXPECT_NE(seedsOut.status, 0);
  EXPECT_THAT(seedsOut.output, HasSubstr("--seeds-out"));
  EXPECT_FALSE(fs::exists(path("s.txt")));
  EXPECT_FALSE(fs::exists(path("p.vtp")));
  expectRefused("bench " + path("swirl_0000.exa") + " --backends cpu --particles 4 --json " +
                    path("swirl_0000.exa"),
                "--json: '" + path("swirl_0000.exa") + "' is the input");
}

// Without a display the viewer fails before loading anything; a clobbering --screenshot fails
// before that.
TEST_F(OutputPaths, ViewRefusesAScreenshotOverItsSeedsBeforeOpeningAWindow) {
  std::ofstream(path("seeds.txt")) << "0.5 0.5 0.5\n";
  const Outcome r =
      amrstream::testing::runAmrstream("view builtin:rotation --seeds " + path("seeds.txt") +
                                           " --frames 1 --screenshot " + path("seeds.txt"),
                                       "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--screenshot: '" + path("seeds.txt") + "' is the input"));
  EXPECT_EQ(contents(path("seeds.txt")), "0.5 0.5 0.5\n");
}

TEST_F(OutputPaths, RealDatasetsProtectTheirCompanionFiles) {
  if (!fs::exists(kRealData)) GTEST_SKIP() << "real datasets not found at " << kRealData;
  const fs::path gerris = copyReal("gerris-ring/ring-end.txt");
  expectRefused("trace " + gerris.string() + " --backend cpu --count 4 --out " + gerris.string(),
                "--out: '" + gerris.string() + "' is the input");

  const fs::path enzo = copyReal("enzo-moving7/DD0010") / "moving7_0010";
  for (const char* suffix : {"", ".hierarchy", ".harrays", ".cpu0000"}) {
    const std::string out = enzo.string() + suffix;
    expectRefused("trace " + enzo.string() + " --backend cpu --count 4 --out " + out,
                  "--out: '" + out + "' is the input");
    // Named by its .hierarchy, the dataset is the same.
    expectRefused("trace " + enzo.string() + ".hierarchy --backend cpu --count 4 --out " + out,
                  "--out: '" + out + "' is the input");
  }

  const fs::path amrex = copyReal("amrex-pelelmex-3d/example_plt_3d");
  expectRefused(
      "trace " + amrex.string() + " --backend cpu --count 4 --out " + (amrex / "Header").string(),
      "--out: '" + (amrex / "Header").string() + "' lies inside the input directory '" +
          amrex.string() + "'");
  expectRefused("trace " + amrex.string() + " --backend cpu --count 4 --out " +
                    (amrex / "Level_0" / "new.vtp").string(),
                "lies inside the input directory '" + amrex.string() + "'");
}

}  // namespace
