// The amrstream executable end to end: commands that work, and bad input that must fail with a
// clear message and a non-zero exit status.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "run_amrstream.hpp"
#include "temp_dir_test.hpp"

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

using amrstream::testing::Outcome;

Outcome run(const std::string& arguments, const std::string& environment = "") {
  return amrstream::testing::runAmrstream(arguments, environment);
}

class Cli : public amrstream::testing::TempDirTest {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
};

const std::string kSmall = " --levels 3 --root-blocks 2 --target-cells 20000";

TEST_F(Cli, TraceBuiltinWritesVtpAndPrintsSummary) {
  const Outcome r = run("trace builtin:rotation" + kSmall +
                        " --backend cpu --steps 50 --count 16 --out " + path("t.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("seeds      16"));
  EXPECT_THAT(r.output, HasSubstr("reasons"));
  EXPECT_THAT(r.output, HasSubstr("particle-steps/s"));
  EXPECT_GT(fs::file_size(path("t.vtp")), 1000u);
}

TEST_F(Cli, GenWritesExaFilesThatInfoAndTraceRead) {
  Outcome r = run("gen abc" + kSmall + " --seed 3 --out " + path("abc"));
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_TRUE(fs::exists(path("abc.exa")));
  std::ifstream exa(path("abc.exa"));
  const std::string exaText((std::istreambuf_iterator<char>(exa)), {});
  EXPECT_THAT(exaText, HasSubstr("\ntime 0\n"));          // abc is steady, at t = 0
  EXPECT_THAT(exaText, HasSubstr("\nperiodic 1 1 1\n"));  // one full period over the unit cube
  r = run("info " + path("abc.exa"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("level 2"));
  EXPECT_THAT(r.output, HasSubstr("bricks"));
  EXPECT_THAT(r.output, HasSubstr("regions"));
  EXPECT_THAT(r.output, HasSubstr("velx"));
  std::ofstream(path("seeds.txt")) << "0.5 0.5 0.5\n0.25, 0.75, 0.5\n";
  r = run("trace " + path("abc.exa") + " --backend cpu --seeds " + path("seeds.txt") +
          " --steps 20 --out " + path("abc.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("seeds      2 from"));
}

// gen nest goes past the other kinds' 8 levels, and each kind refuses the other's sizes.
TEST_F(Cli, GenNestWritesDeepLevelsAndKindsRefuseEachOthersSizes) {
  Outcome r = run("gen nest --levels 14 --root-cells 7 --out " + path("nest"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("builtin:nest: 6,167 cells, levels 0..13"));
  r = run("info " + path("nest.exa"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("levels     14 hold leaf cells"));
  EXPECT_THAT(r.output, HasSubstr("[57344,57344,57344]"));

  r = run("gen rotation --block-cells 8 --out " + path("x"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("--block-cells: sizes kind nest only, not rotation"));
  r = run("gen nest --root-blocks 2 --out " + path("x"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("--root-blocks: does not apply to kind nest"));
  r = run("gen nest --block-cells 9 --out " + path("x"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("option blockCells is 9; it must be even"));
  EXPECT_FALSE(fs::exists(path("x.exa")));
}

TEST_F(Cli, MissingInputFailsNamingTheFile) {
  const Outcome r = run("trace " + path("nothing.exa") + " --out " + path("t.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr(path("nothing.exa") + ": no such file"));
  EXPECT_FALSE(fs::exists(path("t.vtp")));
}

TEST_F(Cli, UnknownBuiltinListsTheKinds) {
  const Outcome r = run("info builtin:nebula");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("nebula"));
  EXPECT_THAT(r.output, HasSubstr("cloud"));
}

TEST_F(Cli, TruncatedCellsFileFailsNamingIt) {
  ASSERT_EQ(run("gen rotation" + kSmall + " --out " + path("rot")).status, 0);
  fs::resize_file(path("rot.cells"), fs::file_size(path("rot.cells")) - 5);
  const Outcome r = run("info " + path("rot.exa"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr(path("rot.cells") + ": size"));
}

TEST_F(Cli, SeedOutsideTheDomainFailsNamingTheLine) {
  std::ofstream(path("seeds.txt")) << "0.5 0.5 0.5\n2 0.5 0.5\n";
  const Outcome r = run("trace builtin:rotation" + kSmall + " --seeds " + path("seeds.txt") +
                        " --out " + path("t.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr(path("seeds.txt") + ":2: seed (2, 0.5, 0.5) is outside"));
}

// Typos get the closest name: an option of the command, or a channel whatever its case.
TEST_F(Cli, TyposAreAnsweredWithTheClosestName) {
  Outcome r = run("trace builtin:rotation" + kSmall + " --cout 5 --out " + path("t.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("amrstream: error: unknown option --cout (did you mean "
                                  "--count?); left over: 5"));
  r = run("trace builtin:rotation" + kSmall + " --sedd-box 0,0,0,1,1,1 --out " + path("t.vtp"));
  EXPECT_THAT(r.output, HasSubstr("unknown option --sedd-box (did you mean --seed-box?)"));
  r = run("trace builtin:rotation" + kSmall + " --frobnicate --out " + path("t.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("amrstream: error: unknown option --frobnicate\n"));
  r = run("trace builtin:cloud" + kSmall + " --vector MAGX,magy,magz --out " + path("t.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("no channel named 'MAGX' (did you mean 'magx'?); the "
                                  "channels are: dens, magx, magy, magz"));
  r = run("trace builtin:cloud" + kSmall + " --point-data dense --out " + path("t.vtp"));
  EXPECT_THAT(r.output, HasSubstr("no channel 'dense' in builtin:cloud (did you mean 'dens'?)"));
  EXPECT_FALSE(fs::exists(path("t.vtp")));
}

// An output's name says what it holds: a PNG is not written to x.jpg, nor a .vtp to x.png.
TEST_F(Cli, OutputsNamedAsAnotherFormatAreRefused) {
  ASSERT_EQ(
      run("gen swirl --levels 2 --root-blocks 1 --target-cells 600 --series 2 --out " + path("sw"))
          .status,
      0);
  const struct {
    std::string command, error;
  } cases[] = {
      {"render builtin:rotation --out " + path("x.jpg"),
       "--out: '" + path("x.jpg") + "': the file written is a PNG image; name it .png"},
      {"trace builtin:rotation --out " + path("x.png"),
       "the file written is VTK XML PolyData; name it .vtp"},
      {"trace builtin:rotation --pieces --out " + path("x.vtp"), "name the .pvtp"},
      {"pathlines '" + path("sw_*.exa") + "' --out " + path("x.pvtp"), "name it .vtp"},
      {"resample builtin:rotation --out " + path("x.vtk"), "VTK XML ImageData; name it .vti"},
      {"bench builtin:rotation --json " + path("x.txt"), "--json: '"},
      {"view builtin:rotation --benchmark --frames 2 --frame-times " + path("x.json"),
       "name it .csv"},
      {"view builtin:rotation --frames 1 --screenshot " + path("x"), "name it .png"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.command);
    const Outcome r = run(c.command);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr(c.error));
  }
  const Outcome upper =
      run("trace builtin:rotation" + kSmall + " --count 2 --steps 2 --out " + path("T.VTP"));
  EXPECT_EQ(upper.status, 0) << upper.output;
  for (const char* name : {"x.jpg", "x.png", "x.pvtp", "x.vtk", "x.txt", "x.json", "x"})
    EXPECT_FALSE(fs::exists(path(name))) << name;
}

// render --traces draws the lines of a file: seeding and stepping options would do nothing.
TEST_F(Cli, RenderingTracesFromAFileRefusesSeedAndStepOptions) {
  ASSERT_EQ(
      run("trace builtin:rotation" + kSmall + " --count 2 --steps 4 --out " + path("t.vtp")).status,
      0);
  for (const std::string option : {"--count 100", "--steps 50", "--seed-box 0,0,0,1,1,1"}) {
    const Outcome r = run("render builtin:rotation" + kSmall + " --traces " + path("t.vtp") + " " +
                          option + " --out " + path("r.png"));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr(option.substr(0, option.find(' ')) +
                                    ": the lines come from --traces " + path("t.vtp")));
  }
  EXPECT_FALSE(fs::exists(path("r.png")));
}

// info says what a new user needs before tracing: a 2D file, cells taller than wide, levels that
// lie wholly under finer ones.
TEST_F(Cli, InfoSaysTheShapeOfTheCellsAndTheLevelsUnderFinerOnes) {
  const fs::path real = AMRSTREAM_REAL_DATA_DIR;
  const fs::path flash = real / "flash-2d-nanowire" / "nanowire_arrayhdf5_plt_cnt_0100";
  const fs::path amrex = real / "amrex-pelelmex-3d" / "example_plt_3d";
  if (!fs::exists(flash) || !fs::exists(amrex)) GTEST_SKIP() << "no real data at " << real;
  Outcome r = run("info " + flash.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("finest     cell 7.8125e-07 x 7.8125e-06 x 7.8125e-07 "
                                  "(anisotropic: 10 to 1)\n"));
  EXPECT_THAT(r.output, HasSubstr("dimensions 2: planar data, held as a slab 1 finest cell thick "
                                  "across z = 0\n"));
  EXPECT_THAT(r.output, HasSubstr("levels     1 hold leaf cells (the file's levels 1 to 4 lie "
                                  "wholly under finer cells)"));
  r = run("info " + amrex.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("levels     1 hold leaf cells (the file's levels 0 to 1 lie "
                                  "wholly under finer cells), numbered as AMReX level"));
  EXPECT_THAT(r.output, Not(HasSubstr("dimensions")));
  EXPECT_THAT(r.output, Not(HasSubstr("anisotropic")));
}

// Units: FLASH states its standard variables'; a format that states none takes --length-unit
// and --unit, which info shows and convert keeps; a unit the file states is not changed, and a
// name that is no channel is refused with the closest one.
TEST_F(Cli, UnitsTheFileStatesOrTheUserDeclares) {
  const fs::path flash =
      fs::path(AMRSTREAM_REAL_DATA_DIR) / "flash-2d-nanowire" / "nanowire_arrayhdf5_plt_cnt_0100";
  if (fs::exists(flash)) {
    Outcome r = run("info " + flash.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_THAT(r.output, testing::ContainsRegex("\n  dens +\\[[^]]+\\] g/cm\\*\\*3\n"));
    EXPECT_THAT(r.output, testing::ContainsRegex("\n  tele +\\[[^]]+\\] K\n"));
    r = run("info " + flash.string() + " --length-unit m");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_THAT(r.output, HasSubstr("--length-unit: " + flash.string() +
                                    " states its lengths in "
                                    "cm; a unit the file states cannot be changed"));
  }
  const std::string declared = " --length-unit kpc --unit velx=km/s --unit vel=km/s";
  Outcome r = run("convert builtin:rotation" + kSmall + declared + " " + path("units"));
  ASSERT_EQ(r.status, 0) << r.output;
  r = run("info " + path("units.exa"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("lengths    kpc\n"));
  EXPECT_THAT(r.output, testing::ContainsRegex("\n  velx +\\[[^]]+\\] km/s\n"));
  EXPECT_THAT(r.output, testing::ContainsRegex("\n  vely +\\[[^]]+\\]\n"));
  r = run("info builtin:rotation" + kSmall + " --unit Velx=km/s");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--unit: 'Velx' is no channel or vector of builtin:rotation "
                                  "(did you mean 'velx'?)"));
  r = run("info builtin:rotation" + kSmall + " --unit velx");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--unit: 'velx': expected NAME=UNIT"));
}

TEST_F(Cli, BadOptionsFail) {
  Outcome r =
      run("trace builtin:rotation" + kSmall + " --seed-box 0,0,0,2,1,1 --out " + path("t.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("--seed-box: the box reaches outside the domain"));
  r = run("trace builtin:rotation" + kSmall + " --vector velx,vely --out " + path("t.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("exactly three channels"));
  r = run("trace builtin:rotation" + kSmall + " --step-mode fast");
  EXPECT_NE(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("--step-mode"));
  r = run("trace builtin:rotation" + kSmall + " --step-size -1");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("--step-size: -1 is not > 0"));
  r = run("gen rotation --levels 12 --out " + path("x"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("levels"));
  // The CPU finishes one process's last lines: not where ranks hand lines on, nor in the viewer.
  r = run("trace builtin:rotation" + kSmall + " --cpu-tail 8 --distribute data --out " +
          path("t.vtp"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("--cpu-tail: finishes the last lines of one process's trace"));
  r = run("view builtin:rotation" + kSmall + " --cpu-tail 8 --benchmark --frames 1");
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("--cpu-tail: the viewer advances every line on the GPU"));
  EXPECT_FALSE(std::filesystem::exists(path("t.vtp")));
}

// An output is written beside its target and renamed over it: a FIFO (or a device such as
// /dev/null) must be refused, not replaced by a regular file.
TEST_F(Cli, AnOutputThatIsNotARegularFileIsRefused) {
  ASSERT_EQ(::mkfifo(path("pipe.vtp").c_str(), 0600), 0);
  const Outcome r = run("trace builtin:rotation" + kSmall +
                        " --backend cpu --steps 5 --count 4 --out " + path("pipe.vtp"));
  EXPECT_NE(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("exists and is not a regular file"));
  EXPECT_FALSE(fs::is_regular_file(path("pipe.vtp")));
  EXPECT_TRUE(fs::is_fifo(path("pipe.vtp")));
}

TEST_F(Cli, UnwritableOutputFails) {
  const Outcome r = run("trace builtin:rotation" + kSmall +
                        " --backend cpu --steps 5 --count 4 --out " + path("no/such/dir/t.vtp"));
  EXPECT_NE(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr(path("no/such/dir/t.vtp")));
}

}  // namespace

namespace {

TEST_F(Cli, ConvertWritesExaBricksFilesThatReadBackTheSame) {
  Outcome r = run("convert builtin:abc" + kSmall + " " + path("abc.exa"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("(builtin)"));
  const Outcome original = run("info builtin:abc" + kSmall);
  const Outcome converted = run("info " + path("abc.exa"));
  ASSERT_EQ(converted.status, 0) << converted.output;
  // The same cells per level and widths (the level numbers differ: generator levels count from
  // the root, ExaBricks levels from the finest), bounds and channels.
  const auto levelCounts = [](const std::string& out) {
    std::string counts;
    for (std::size_t at = out.find("\n  level "); at != std::string::npos;
         at = out.find("\n  level ", at + 1))
      counts += out.substr(out.find("  ", at + 9), out.find('\n', at + 1) - out.find("  ", at + 9));
    return counts;
  };
  EXPECT_THAT(levelCounts(original.output), HasSubstr("cells  width 4"));
  EXPECT_EQ(levelCounts(converted.output), levelCounts(original.output));
  const auto fromBounds = [](const std::string& out) {
    return out.substr(out.find("bounds     "));
  };
  EXPECT_EQ(fromBounds(converted.output).substr(0, 200),
            fromBounds(original.output).substr(0, 200));
  // What the builtin dataset says about itself travels in the .exa.
  EXPECT_THAT(original.output, HasSubstr("periodic   x y z\n"));
  EXPECT_THAT(converted.output, HasSubstr("periodic   x y z\n"));
  EXPECT_THAT(converted.output, HasSubstr("time       0 (unit unknown)\n"));
  EXPECT_THAT(converted.output, HasSubstr("numbered as ExaBricks level (0 = finest)"));
}

TEST_F(Cli, HelpSaysWhichInputsAreAccepted) {
  for (const char* command : {"info", "trace", "convert", "bench", "render"}) {
    const Outcome r = run(std::string(command) + " --help");
    EXPECT_EQ(r.status, 0) << r.output;
    for (const char* input :
         {"FLASH", "Enzo", "AMReX plotfile", "Gerris", ".exa", "builtin:rotation|abc|cloud"})
      EXPECT_THAT(r.output, HasSubstr(input)) << command;
    EXPECT_THAT(r.output, Not(HasSubstr("an ExaBricks .exa file or builtin:NAME"))) << command;
  }
}

TEST_F(Cli, BenchRejectsBadCountsAndTooFewSeeds) {
  Outcome r = run("bench builtin:rotation" + kSmall + " --backends cpu --particles 0 --json " +
                  path("b.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("--particles"));
  std::ofstream(path("three.txt")) << "1 1 1\n2 2 2\n3 3 3\n";
  r = run("bench builtin:rotation" + kSmall + " --backends cpu --particles 4 --seeds " +
          path("three.txt") + " --json " + path("b.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.output, HasSubstr("three.txt"));
  EXPECT_THAT(r.output, HasSubstr("fewer than the largest particle count 4"));
  EXPECT_FALSE(fs::exists(path("b.json")));
}

TEST_F(Cli, InfoAndTraceReadEveryRealDataset) {
  const fs::path real(AMRSTREAM_REAL_DATA_DIR);
  if (!fs::exists(real)) GTEST_SKIP() << "real datasets not found at " << real;
  const std::vector<std::pair<std::string, std::string>> inputs{
      {"enzo-moving7/DD0010/moving7_0010", "27,077"},
      {"amrex-pelelmex-3d/example_plt_3d", "32,768"},
      {"gerris-ring/ring-end.txt", "69,441"},
      {"flash-2d-nanowire/nanowire_arrayhdf5_plt_cnt_0100", "65,536"}};
  for (const auto& [input, cells] : inputs) {
    const std::string file = (real / input).string();
    Outcome r = run("info " + file);
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_THAT(r.output, HasSubstr("cells      " + cells));
    // FLASH's nanowire file has no vector field: any three channels exercise the path.
    const std::string vector = input.starts_with("flash") ? " --vector tele,tion,trad" : "";
    r = run("trace " + file + vector + " --backend cpu --steps 50 --count 32 --out " +
            path("real.vtp"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_THAT(r.output, HasSubstr("seeds      32"));
  }
}

// "1234567" -> "1,234,567", as amrstream prints counts.
std::string withCommas(long n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// `Key = value` lines of one `Grid = N` block of an Enzo .hierarchy file.
std::map<int, std::map<std::string, std::string>> hierarchyBlocks(const fs::path& file) {
  std::map<int, std::map<std::string, std::string>> blocks;
  std::ifstream in(file);
  int grid = 0;
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    std::string key = line.substr(0, eq);
    key.erase(key.find_last_not_of(' ') + 1);
    const std::string value = line.substr(eq + 1);
    if (key == "Grid")
      grid = std::stoi(value);
    else
      blocks[grid][key] = value;
  }
  return blocks;
}

// Enzo numbers levels from the root grid (0) down; `info` must too, coarsest first, and its level
// 0 must hold the root grid's leaf cells: the 16^3 root cells less those under level-1 grids.
TEST_F(Cli, InfoNumbersEnzoLevelsFromTheRootGrid) {
  const fs::path dir = fs::path(AMRSTREAM_REAL_DATA_DIR) / "enzo-moving7" / "DD0010";
  if (!fs::exists(dir)) GTEST_SKIP() << "real Enzo data not found at " << dir;
  // Oracle from the .hierarchy text: a level-1 grid has cells half the root's (1/16) wide, and
  // each of its cells covers 1/8 of a root cell.
  long rootLeaves = 0, underLevelOne = 0;
  for (const auto& [grid, keys] : hierarchyBlocks(dir / "moving7_0010.hierarchy")) {
    std::istringstream start(keys.at("GridStartIndex")), end(keys.at("GridEndIndex")),
        left(keys.at("GridLeftEdge")), right(keys.at("GridRightEdge"));
    long cells = 1;
    double cellSize = 0;
    for (int a = 0; a < 3; ++a) {
      int s, e;
      double l, r;
      start >> s;
      end >> e;
      left >> l;
      right >> r;
      cells *= e - s + 1;
      cellSize = (r - l) / (e - s + 1);
    }
    if (grid == 1) rootLeaves = cells;
    if (std::abs(cellSize - 1.0 / 32) < 1e-9) underLevelOne += cells / 8;
  }
  ASSERT_EQ(rootLeaves, 16 * 16 * 16);
  ASSERT_GT(underLevelOne, 0);

  const Outcome r = run("info " + (dir / "moving7_0010").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("format     Enzo\n"));
  EXPECT_THAT(r.output, HasSubstr("periodic   x y z\n"));
  EXPECT_THAT(r.output, HasSubstr("time       0.817513171 code units (1 = "));
  EXPECT_THAT(r.output,
              HasSubstr("levels     8 hold leaf cells, numbered as Enzo level (0 = root grid)"));
  const std::size_t level0 = r.output.find("\n  level 0 ");
  ASSERT_NE(level0, std::string::npos) << r.output;
  const std::string line =
      r.output.substr(level0 + 1, r.output.find('\n', level0 + 1) - level0 - 1);
  EXPECT_THAT(line, HasSubstr(" " + withCommas(rootLeaves - underLevelOne) + " cells"));
  EXPECT_THAT(line, HasSubstr("width 128"));  // 2^7 finest cells: root dx 1/16, finest 1/2048
  for (int level = 1; level <= 7; ++level)    // coarsest first
    EXPECT_GT(r.output.find("\n  level " + std::to_string(level) + " "), level0) << level;

  const Outcome trace = run("trace " + (dir / "moving7_0010").string() +
                            " --backend cpu --steps 5 --count 4 --out " + path("enzo.vtp"));
  ASSERT_EQ(trace.status, 0) << trace.output;
  EXPECT_THAT(trace.output, HasSubstr(", t = 0.817513171 code units (1 = "));
  EXPECT_THAT(trace.output, HasSubstr(", lengths in code units (1 = "));
}

// Without a display the viewer fails at once, saying what to do, before loading the input.
TEST_F(Cli, ViewWithoutADisplaySaysWhatToDo) {
  const auto r = run("view builtin:cloud", "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("cannot open a window: no display"));
  EXPECT_THAT(r.output, HasSubstr("xvfb-run"));
  EXPECT_THAT(r.output, Not(HasSubstr("structure ")));
}

}  // namespace

namespace {

// The seed grid sets the number of seeds; a --count beside it would be ignored, so it is refused.
TEST_F(Cli, SeedGridRefusesCount) {
  const Outcome r = run("trace builtin:rotation" + kSmall + " --seed-grid 2,2,2 --count 10 --out " +
                        path("t.vtp"));
  EXPECT_NE(r.status, 0);
  EXPECT_THAT(r.output, HasSubstr("--seed-grid excludes --count"));
  EXPECT_FALSE(fs::exists(path("t.vtp")));
}

// A rake between the domain's corners: its last seed lies on the open upper faces and is moved
// just inside.
TEST_F(Cli, SeedLineMayEndAtTheDomainsUpperCorner) {
  const Outcome r =
      run("trace builtin:rotation" + kSmall +
          " --backend cpu --seed-line 0,0,0,1,1,1 --count 5 --steps 10 --out " + path("t.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("seeds      5 from a rake"));
}

// `auto` traces with the fastest: the CPU reference where the only Vulkan devices are software
// ones (lavapipe), a GPU backend otherwise; `devices` says the same.
TEST_F(Cli, AutoTracesOnTheCpuWhenTheOnlyDeviceIsASoftwareOne) {
  const Outcome devices = run("devices");
  ASSERT_EQ(devices.status, 0) << devices.output;
  const bool gpu = devices.output.find("discrete GPU") != std::string::npos ||
                   devices.output.find("integrated GPU") != std::string::npos;
  const Outcome r =
      run("trace builtin:rotation" + kSmall + " --count 8 --steps 10 --out " + path("t.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  if (gpu) {
    EXPECT_THAT(r.output, Not(HasSubstr("backend    auto: cpu")));
  } else {
    EXPECT_THAT(r.output, HasSubstr("backend    auto: cpu ("));
    EXPECT_THAT(devices.output, HasSubstr("cpu for trace"));
  }
}

TEST_F(Cli, EnzoIsPeriodicAsItsParameterFileSays) {
  const fs::path real(AMRSTREAM_REAL_DATA_DIR);
  if (!fs::exists(real)) GTEST_SKIP() << "real datasets not found at " << real;
  const std::string enzo = (real / "enzo-moving7/DD0010/moving7_0010").string();
  Outcome r =
      run("trace " + enzo + " --backend cpu --steps 2000 --count 64 --out " + path("enzo.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("periodic images (x,y,z)"));
  EXPECT_THAT(r.output, Not(HasSubstr("out of domain")));  // nothing leaves a periodic box
  r = run("trace " + enzo + " --periodic none --backend cpu --steps 2000 --count 64 --out " +
          path("enzo.vtp"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("out of domain"));
  r = run("trace " + enzo + " --periodic xq --out " + path("enzo.vtp"));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("--periodic"));
}

}  // namespace

// slice: a figure and the plane's samples; bad planes, channels and colours fail naming the
// option, before any file is written.
TEST_F(Cli, SliceWritesTheFigureAndThePlaneAndRefusesBadOptions) {
  const std::string out = " --out " + path("s.png") + " --vti " + path("s.vti");
  const struct {
    std::string options, message;
  } cases[] = {
      {"--normal 0,0,0", "--normal: '0,0,0' is neither x, y, z nor a non-zero NX,NY,NZ"},
      {"--point 2,0.5,0.5", "--point: (2, 0.5, 0.5) is outside the domain"},
      {"--window 3,3,4,4", "--window: [3, 4] x [3, 4] misses the domain"},
      {"--background nosuch", "--background: 'nosuch' is not a channel of the point data"},
      {"--colour-scale cubic", "--colour-scale"},
      {"--range 2,1", "--range"},
      {"--line-colour-by nosuch", "--line-colour-by: 'nosuch' is not a channel"},
      {"--lic --lic-length 1000", "--lic-length: 1000 is 32000 pixels each way"},
  };
  for (const auto& c : cases) {
    const Outcome r = run("slice builtin:cloud" + kSmall + " --width 32 " + c.options + out);
    EXPECT_NE(r.status, 0) << c.options;
    EXPECT_THAT(r.output, HasSubstr(c.message)) << c.options;
    EXPECT_FALSE(fs::exists(path("s.png"))) << c.options;
  }
  const Outcome r = run("slice builtin:cloud" + kSmall + " --width 64 --lic --normal y" + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("64 x 64 pixels across y"));
  EXPECT_THAT(r.output, HasSubstr("background dens"));
  EXPECT_THAT(r.output, HasSubstr("evenly spaced"));
  EXPECT_TRUE(fs::exists(path("s.png")));
  EXPECT_TRUE(fs::exists(path("s.vti")));
}

// resample: bad grids, boxes and channels fail naming the option, before any file is written.
TEST_F(Cli, ResampleRefusesBadGridsAndLeavesNoFile) {
  const std::string out = " --out " + path("g.vti");
  const struct {
    std::string options, message;
  } cases[] = {
      {"--dims 0", "--dims"},
      {"--dims 4,4", "--dims: give one count (the longest axis) or three"},
      {"--dims 65535,65535,65535", "more than the"},
      {"--box 1,0,0,0,1,1", "--box: each upper bound must be above its lower bound"},
      {"--point-data nosuch", "nosuch"},
      {"--compression gzip", "--compression"},
  };
  for (const auto& c : cases) {
    const Outcome r = run("resample builtin:rotation" + kSmall + " " + c.options + out);
    EXPECT_NE(r.status, 0) << c.options;
    EXPECT_THAT(r.output, HasSubstr(c.message)) << c.options;
    EXPECT_FALSE(fs::exists(path("g.vti"))) << c.options;
  }
  const Outcome r = run("resample builtin:rotation" + kSmall + " --dims 8" + out);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("8 x 8 x 8 points"));
  EXPECT_TRUE(fs::exists(path("g.vti")));
}
