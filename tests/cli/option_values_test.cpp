// Option values taken on trust before: counts beyond their documented bounds or beyond memory,
// numbers with trailing text, signs, leading zeros (octal to CLI11), and infinities or NaN. Each
// is refused at once with status 2 and a message naming the option and the value, and the run
// writes nothing.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "run_amrstream.hpp"
#include "temp_dir_test.hpp"

namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
using amrstream::testing::Outcome;

const std::string kSmall = " --levels 3 --root-blocks 2 --target-cells 20000";

double physicalMemory() { return double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE)); }

class OptionValues : public amrstream::testing::TempDirTest {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Runs `command` (with a time limit: a value taken on trust would run for hours) and expects
  // status 2, `message`, and nothing written.
  void expectRefused(const std::string& command, const std::string& message) {
    const Outcome r = amrstream::testing::runAmrstream(command, "timeout 60");
    EXPECT_EQ(r.status, 2) << command << "\n" << r.output;
    EXPECT_THAT(r.output, HasSubstr(message)) << command;
    EXPECT_TRUE(fs::is_empty(dir_)) << command;
  }
  std::string trace(const std::string& options) const {
    return "trace builtin:rotation" + kSmall + " --backend cpu --steps 5 " + options + " --out " +
           path("t.vtp");
  }
  std::string render(const std::string& options) const {
    return "render builtin:rotation" + kSmall + " --count 4 --steps 5 " + options + " --out " +
           path("r.png");
  }
};

TEST_F(OptionValues, SeedCountsBeyondTheLimitAreRefusedBeforeAnySeedIsMade) {
  for (const char* count :
       {"1000000000000", "4294967296", "18446744073709551615", "99999999999999999999"})
    expectRefused(trace(std::string("--count ") + count),
                  std::string("--count: ") + count + " is outside the range 1 to 2147483647");
  expectRefused(trace("--count 0"), "--count: 0 is outside the range 1 to 2147483647");
  expectRefused(trace("--seed-grid 100000,100000,100000"),
                "--seed-grid: 1000000000000000 seeds are more than the 2147483647 one run may "
                "trace");
  expectRefused(trace("--seed-grid 65536,65536,1"), "--seed-grid: 4294967296 seeds are more");
  expectRefused(trace("--seed-grid 4,4,3000000000"),
                "--seed-grid: 3000000000 is outside the range 1 to 2147483647");
  expectRefused(
      "pathlines builtin:swirl builtin:swirl --seed-grid 65536,65536,1 --out " + path("p.vtp"),
      "--seed-grid: 4294967296 seeds are more");
  expectRefused("bench builtin:rotation" + kSmall +
                    " --backends cpu --particles 16,4294967296 "
                    "--json " +
                    path("b.json"),
                "--particles: 4294967296 is outside the range 1 to 2147483647");
}

// Within the 32-bit limit, the memory a seed needs at the least (388 bytes: the seed, the text
// naming it, and a line of one point with its bookkeeping) decides.
TEST_F(OptionValues, SeedCountsBeyondMemoryAreRefusedWithTheNumbers) {
  if (2e9 * 388.0 <= 0.75 * physicalMemory()) GTEST_SKIP() << "this machine could hold 2e9 seeds";
  expectRefused(trace("--count 2147483647"),
                "--count: 2147483647 seeds need at least 776.0 GiB (388 bytes each for the seed "
                "and its traced line), more than the ");
  expectRefused(trace("--seed-line 0,0,0,1,1,1 --count 2147483647"), "seeds need at least");
  expectRefused(trace("--seed-density velx --count 2147483647"), "seeds need at least");
  expectRefused(trace("--seed-grid 2000,1000,1000"), "--seed-grid: 2000000000 seeds need at least");
}

TEST_F(OptionValues, CountsMustBePlainDecimalNumbersInRange) {
  expectRefused(trace("--count 5x"), "--count: '5x' is not a whole number from 1 to 2147483647");
  expectRefused(trace("--count 1e3"), "--count: '1e3' is not a whole number");
  expectRefused(trace("--count 0x10"), "--count: '0x10' is not a whole number");
  expectRefused(trace("--count 010"), "--count: '010' has a leading zero");
  expectRefused(trace("--count=-1"), "--count: '-1' is not a whole number");
  expectRefused(trace("--steps 4294967296"),
                "--steps: 4294967296 is outside the range 0 to "
                "1000000000");
  expectRefused(trace("--steps 10k"), "--steps: '10k' is not a whole number");
  expectRefused(trace("--seed 18446744073709551616"), "--seed: 18446744073709551616 is outside");
  expectRefused(trace("--memory-budget 1P"),
                "--memory-budget: 1125899906842624 is outside the "
                "range 0 to ");
  expectRefused("info builtin:rotation --target-cells 99999999999999",
                "--target-cells: 99999999999999 is outside the range 1 to 2147483647");
  expectRefused("info builtin:rotation --levels 9", "--levels: 9 is outside the range 1 to 8");
  expectRefused("gen rotation --series 010 --out " + path("g"), "--series: '010' has a leading");
  expectRefused("bench builtin:rotation" + kSmall + " --backends cpu --repeats 4294967295 --json " +
                    path("b.json"),
                "--repeats: 4294967295 is outside the range 1 to 1000");
}

TEST_F(OptionValues, RealNumbersMustBeFiniteAndInRange) {
  for (const char* option : {"--step-size", "--terminal-speed", "--max-length", "--max-time"})
    for (const char* value : {"inf", "nan", "-inf", "1e39"})
      expectRefused(trace(std::string(option) + "=" + value), std::string(option) + ": ");
  expectRefused(trace("--step-size=0"),
                "--step-size: 0 is not > 0 (from 1.17549e-38 to "
                "3.40282e+38)");
  expectRefused(trace("--step-size=1e-50"), "--step-size: 1e-50 is not > 0");  // 0 as a float
  expectRefused(trace("--terminal-speed=-1"), "--terminal-speed: -1 is not >= 0");
  expectRefused(trace("--max-length=-1"), "--max-length: -1 is not >= 0");
  expectRefused(trace("--seed-box 0,0,0,1,1,1e39"),
                "--seed-box: 1e39 is not finite in float's range");
  expectRefused(trace("--max-length=nan"), "--max-length: 'nan' is not a finite number");
  expectRefused(trace("--step-size 0.1x"), "--step-size: '0.1x' is not a number");
  expectRefused(trace("--step-size 0x1p-2"), "--step-size: '0x1p-2' is not a number");
  expectRefused(trace("--seed-box 0,0,0,1,1,nan"), "--seed-box: 'nan' is not a finite number");
  expectRefused(trace("--seed-line 0,0,0,1,1,inf"), "--seed-line: 'inf' is not a finite number");
  expectRefused(trace("--seed-density velx --seed-percentile 101"),
                "--seed-percentile: 101 is outside the range 0 to 100");
  expectRefused("pathlines builtin:swirl builtin:swirl --step-size inf --out " + path("p.vtp"),
                "--step-size: 'inf' is not a finite number");
  expectRefused("pathlines builtin:swirl builtin:swirl --end-time nan --out " + path("p.vtp"),
                "--end-time: 'nan' is not a finite number");
  expectRefused("pathlines builtin:swirl builtin:swirl --release-every 0 --out " + path("p.vtp"),
                "--release-every: 0 is not > 0");
  expectRefused("gen swirl --time nan --out " + path("g"), "--time: 'nan' is not a finite number");
  expectRefused("gen swirl --series 2 --interval inf --out " + path("g"),
                "--interval: 'inf' is not a finite number");
}

// render's options are checked while parsing, before a device or the input is touched.
TEST_F(OptionValues, RenderOptionsAreBoundedAndFinite) {
  expectRefused(render("--camera nan,20"), "--camera: 'nan' is not a finite number");
  expectRefused(render("--camera 30,20,inf"), "--camera: 'inf' is not a finite number");
  // Elevations past straight above or below the centre, and azimuths of many turns, were taken
  // (elevation clamped to +-90, azimuth to float's precision).
  expectRefused(render("--camera 30,200"), "--camera: 200 is outside the range -90 to 90");
  expectRefused(render("--camera 30,-90.5"), "--camera: -90.5 is outside the range -90 to 90");
  expectRefused(render("--camera 1e30,20"), "--camera: 1e30 is outside the range -360 to 360");
  expectRefused("view builtin:rotation --camera 400,20",
                "--camera: 400 is outside the range -360 to 360");
  expectRefused(render("--view-box 0,0,0,1,1,1e999"), "--view-box: '1e999' is not a finite");
  expectRefused(render("--tube-radius=-1"), "--tube-radius: -1 is not > 0");
  expectRefused(render("--range 0,inf"), "--range: 'inf' is not a finite number");
  expectRefused(render("--volume-range nan,1"), "--volume-range: 'nan' is not a finite number");
  expectRefused(render("--volume-opacity inf"), "--volume-opacity: 'inf' is not a finite number");
  expectRefused(render("--ao-samples 4294967295"),
                "--ao-samples: 4294967295 is outside the range 0 to 256");
  expectRefused(render("--frames 4294967295"),
                "--frames: 4294967295 is outside the range 1 to 4096");
  expectRefused(render("--frames 0"), "--frames: 0 is outside the range 1 to 4096");
  expectRefused(render("--width 1024px"),
                "--width: '1024px' is not a whole number from 16 to "
                "16384");
  expectRefused(render("--height 100000"), "--height: 100000 is outside the range 16 to 16384");
  expectRefused("view builtin:rotation --frames 4294967295",
                "--frames: 4294967295 is outside the range 0 to 1000000");
  expectRefused("view builtin:rotation --steps-per-frame 0", "--steps-per-frame: 0 is outside");
  expectRefused("view builtin:rotation --orbit-per-frame nan",
                "--orbit-per-frame: 'nan' is not a finite number");
}

// Builtin datasets are sized before they are generated: 2^31 - 1 cells take at least 50 GiB
// (25 bytes each), and 8 levels of 255^3 root blocks could make them.
TEST_F(OptionValues, BuiltinDatasetsBeyondMemoryAreRefusedBeforeGenerating) {
  if (2147483647.0 * 25.0 <= 0.75 * physicalMemory())
    GTEST_SKIP() << "this machine could hold 2^31 - 1 cells";
  expectRefused("info builtin:rotation --levels 8 --root-blocks 255 --target-cells 2147483647",
                "--target-cells: 2147483647 cells need at least");
}

// A FIFO without a writer would block the reader, a device never end: refused by name.
TEST_F(OptionValues, InputFilesMustBeRegularFiles) {
  const fs::path fifo = fs::temp_directory_path() / ("amrstream-fifo-" + std::to_string(getpid()));
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  expectRefused(trace("--seeds " + fifo.string()),
                "--seeds: " + fifo.string() + ": is a FIFO (named pipe), not a regular file");
  expectRefused(render("--traces " + fifo.string()), "--traces: " + fifo.string() + ": is a FIFO");
  expectRefused("bench builtin:rotation --seeds " + fifo.string() + " --json " + path("b.json"),
                "--seeds: " + fifo.string() + ": is a FIFO");
  fs::remove(fifo);
  expectRefused(render("--traces /dev/zero"), "--traces: /dev/zero: is a device, not a regular");
  expectRefused(trace("--seeds /dev/null"), "--seeds: /dev/null: is a device");
  expectRefused(trace("--seeds " + fs::temp_directory_path().string()), "is a directory");
  expectRefused(trace("--seeds " + path("none.txt")),
                "--seeds: " + path("none.txt") + ": no such file");
}

}  // namespace
