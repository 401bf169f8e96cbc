// AMReX plotfiles: the real PeleLMeX plotfile and a synthetic two-level plotfile with known values
// read back cell by cell, covered coarse cells dropped, with their time, level numbers and
// periodicity (from job_info); damaged plotfiles are rejected naming the file.

#include "formats/amrex/amrex_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "amrstream/error.hpp"
#include "formats/amrex/amrex_info.hpp"
#include "input_error_of.hpp"
#include "special_files.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

const fs::path kRealPlotfile =
    fs::path(AMRSTREAM_REAL_DATA_DIR) / "amrex-pelelmex-3d" / "example_plt_3d";

// Synthetic plotfile: prob box (-1,0,2)-(1,2,4); level 0 is (0..7)^3 (dx 0.25) in two boxes,
// level 1 (dx 0.125) refines coarse cells (2..5, 0..3, 0..3) with two boxes stored in reverse
// order in one file.
const glm::dvec3 kProbLo(-1.0, 0.0, 2.0);
double valueA(glm::dvec3 p) { return 1.0 + p.x + 2.0 * p.y + 3.0 * p.z; }
double valueB(glm::dvec3 p, int level) { return p.x * p.y - p.z + 10.0 * level; }

struct SynthBox {
  glm::ivec3 lo, hi;
};

std::string boxText(const SynthBox& b) {
  std::ostringstream out;
  out << "((" << b.lo.x << ',' << b.lo.y << ',' << b.lo.z << ") (" << b.hi.x << ',' << b.hi.y << ','
      << b.hi.z << ") (0,0,0))";
  return out.str();
}

enum class Real { kFloat64Little, kFloat64Big, kFloat32Little };

std::string fabBytes(const SynthBox& b, int level, Real real = Real::kFloat64Little) {
  const double dx = 0.25 / (1 << level);
  const char* descriptor =
      real == Real::kFloat64Little ? "(8, (64 11 52 0 1 12 0 1023)),(8, (8 7 6 5 4 3 2 1))"
      : real == Real::kFloat64Big  ? "(8, (64 11 52 0 1 12 0 1023)),(8, (1 2 3 4 5 6 7 8))"
                                   : "(4, (32 8 23 0 1 9 0 127)),(4, (4 3 2 1))";
  std::string text = std::string("FAB (") + descriptor + ")" + boxText(b) + " 2\n";
  for (int c = 0; c < 2; ++c)
    for (int k = b.lo.z; k <= b.hi.z; ++k)
      for (int j = b.lo.y; j <= b.hi.y; ++j)
        for (int i = b.lo.x; i <= b.hi.x; ++i) {
          const glm::dvec3 p = kProbLo + (glm::dvec3(i, j, k) + 0.5) * dx;
          const double v = c == 0 ? valueA(p) : valueB(p, level);
          char bytes[8];  // the test host is little endian
          if (real == Real::kFloat32Little) {
            const float f = static_cast<float>(v);
            std::memcpy(bytes, &f, 4);
            text.append(bytes, 4);
            continue;
          }
          std::memcpy(bytes, &v, 8);
          if (real == Real::kFloat64Big) std::reverse(bytes, bytes + 8);
          text.append(bytes, 8);
        }
  return text;
}

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// `mixedReals`: level 0's two FABs are float32 and big-endian float64 instead.
void writeSyntheticPlotfile(const fs::path& dir, bool mixedReals = false) {
  const std::vector<std::vector<SynthBox>> boxes = {
      {{{0, 0, 0}, {3, 7, 7}}, {{4, 0, 0}, {7, 7, 7}}},
      {{{4, 0, 0}, {7, 7, 7}}, {{8, 0, 0}, {11, 7, 7}}}};
  std::ostringstream header;
  header << "HyperCLaw-V1.1\n2\nA\nB\n3\n0.5\n1\n-1 0 2\n1 2 4\n2\n"
         << "((0,0,0) (7,7,7) (0,0,0)) ((0,0,0) (15,15,15) (0,0,0))\n0 0\n"
         << "0.25 0.25 0.25\n0.125 0.125 0.125\n0\n0\n";
  for (int level = 0; level < 2; ++level) {
    const double dx = 0.25 / (1 << level);
    header << level << " 2 0.5\n0\n";
    for (const SynthBox& b : boxes[level])
      for (int a = 0; a < 3; ++a)
        header << kProbLo[a] + b.lo[a] * dx << ' ' << kProbLo[a] + (b.hi[a] + 1) * dx << '\n';
    header << "Level_" << level << "/Cell\n";
    const fs::path levelDir = dir / ("Level_" + std::to_string(level));
    fs::create_directories(levelDir);
    std::ostringstream cellH;
    cellH << "1\n1\n2\n0\n(2 0\n"
          << boxText(boxes[level][0]) << '\n'
          << boxText(boxes[level][1]) << "\n)\n2\n";
    const bool mixed = mixedReals && level == 0;
    const std::string fab0 =
        fabBytes(boxes[level][0], level, mixed ? Real::kFloat32Little : Real::kFloat64Little);
    const std::string fab1 =
        fabBytes(boxes[level][1], level, mixed ? Real::kFloat64Big : Real::kFloat64Little);
    if (level == 0) {  // one file per box
      writeFile(levelDir / "Cell_D_00000", fab0);
      writeFile(levelDir / "Cell_D_00001", fab1);
      cellH << "FabOnDisk: Cell_D_00000 0\nFabOnDisk: Cell_D_00001 0\n";
    } else {  // both boxes in one file, box 1 first
      writeFile(levelDir / "Cell_D_00000", fab1 + fab0);
      cellH << "FabOnDisk: Cell_D_00000 " << fab1.size() << "\nFabOnDisk: Cell_D_00000 0\n";
    }
    writeFile(levelDir / "Cell_H", cellH.str());
  }
  writeFile(dir / "Header", header.str());
}

class AmrexReader : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    writeSyntheticPlotfile(dir_);
  }
  std::string errorOf() {
    return testing::inputErrorOf([&] { readAmrexPlotfile(dir_); });
  }
  static std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
  }
  // Replaces the first `from` in `path` by `to`.
  static void replaceIn(const fs::path& path, const std::string& from, const std::string& to) {
    std::string bytes = readBytes(path);
    const std::size_t at = bytes.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    bytes.replace(at, from.size(), to);
    writeFile(path, bytes);
  }
};

constexpr const char* kFloat64Little = "(8, (64 11 52 0 1 12 0 1023)),(8, (8 7 6 5 4 3 2 1))";
constexpr const char* kFloat32Little = "(4, (32 8 23 0 1 9 0 127)),(4, (4 3 2 1))";

void expectSyntheticLeaves(const bricks::AmrField& field) {
  ASSERT_EQ(field.channels().size(), 2u);
  EXPECT_EQ(field.channels()[0].name, "A");
  EXPECT_EQ(field.channels()[1].name, "B");
  EXPECT_EQ(field.transform().origin, kProbLo);
  EXPECT_EQ(field.transform().spacing, glm::dvec3(0.125));
  // 512 fine cells; 512 coarse cells less the 4^3 under the fine boxes.
  EXPECT_EQ(field.cellsPerLevel(), (std::vector<std::size_t>{512, 448}));
  EXPECT_EQ(field.bounds().lower, glm::ivec3(0));
  EXPECT_EQ(field.bounds().upper, glm::ivec3(16));
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const int level = field.levels()[i];
    const glm::ivec3 lower = field.lowers()[i];
    const bool underFine = lower.x >= 4 && lower.x < 12 && lower.y < 8 && lower.z < 8;
    EXPECT_EQ(level == 0, underFine) << "cell " << i << " level " << level;
    const glm::dvec3 centre =
        field.transform().toPhysical(glm::dvec3(lower) + 0.5 * field.cellWidth(level));
    EXPECT_FLOAT_EQ(field.channels()[0].values[i], float(valueA(centre))) << i;
    EXPECT_FLOAT_EQ(field.channels()[1].values[i], float(valueB(centre, 1 - level))) << i;
  }
}

TEST_F(AmrexReader, ReadsLeavesOfTwoLevelPlotfile) {
  expectSyntheticLeaves(readAmrexPlotfile(dir_));
}

TEST_F(AmrexReader, ReadsFloat32AndBigEndianFabs) {
  writeSyntheticPlotfile(dir_, true);
  expectSyntheticLeaves(readAmrexPlotfile(dir_));
}

TEST_F(AmrexReader, RejectsTruncatedData) {
  const fs::path file = dir_ / "Level_1" / "Cell_D_00000";
  const std::string bytes = readBytes(file);
  writeFile(file, bytes.substr(0, bytes.size() - 100));
  const std::string error = errorOf();
  EXPECT_THAT(error, HasSubstr(file.string()));
  EXPECT_THAT(error, HasSubstr("truncated"));
  EXPECT_THAT(error, HasSubstr(std::to_string(bytes.size() - 100) + " bytes"));
}

TEST_F(AmrexReader, RejectsCorruptedFabHeader) {
  const fs::path file = dir_ / "Level_0" / "Cell_D_00001";
  std::string bytes = readBytes(file);
  bytes.replace(bytes.find("(4,0,0)"), 7, "(4;0,0)");
  writeFile(file, bytes);
  EXPECT_THAT(errorOf(), HasSubstr(file.string()));
}

TEST_F(AmrexReader, RejectsFabBoxDifferingFromCellH) {
  const fs::path file = dir_ / "Level_0" / "Cell_D_00001";
  std::string bytes = readBytes(file);
  bytes.replace(bytes.find("(4,0,0)"), 7, "(5,0,0)");
  writeFile(file, bytes);
  EXPECT_THAT(errorOf(), ::testing::AllOf(HasSubstr(file.string()), HasSubstr("differs")));
}

TEST_F(AmrexReader, RejectsMissingFiles) {
  fs::remove(dir_ / "Level_1" / "Cell_D_00000");
  EXPECT_THAT(errorOf(), HasSubstr((dir_ / "Level_1" / "Cell_D_00000").string()));
  fs::remove(dir_ / "Level_1" / "Cell_H");
  EXPECT_THAT(errorOf(), HasSubstr((dir_ / "Level_1" / "Cell_H").string()));
  fs::remove(dir_ / "Header");
  EXPECT_THAT(errorOf(), ::testing::AllOf(HasSubstr(dir_.string()), HasSubstr("Header")));
}

TEST_F(AmrexReader, RejectsComponentCountMismatch) {
  const fs::path cellH = dir_ / "Level_0" / "Cell_H";
  std::string text = readBytes(cellH);
  text.replace(text.find("1\n1\n2\n"), 6, "1\n1\n3\n");
  writeFile(cellH, text);
  EXPECT_THAT(errorOf(), ::testing::AllOf(HasSubstr(cellH.string()), HasSubstr("3 components")));
}

// ---- hardening: domains, boxes, FAB declarations, values, paths that are not files ---------

TEST_F(AmrexReader, BoxesOutsideTheirLevelsDomainAreRefused) {
  const fs::path cellH = dir_ / "Level_1" / "Cell_H";
  replaceIn(cellH, "((8,0,0) (11,7,7) (0,0,0))", "((14,0,0) (17,7,7) (0,0,0))");
  EXPECT_THAT(errorOf(), AllOf(HasSubstr(cellH.string()),
                               HasSubstr("box 1 (14,0,0)-(17,7,7) lies outside the level-1 domain "
                                         "(0,0,0)-(15,15,15)")));
}

TEST_F(AmrexReader, HugeDomainsAndBoxCountsAreRefusedWithoutOverflow) {
  const fs::path header = dir_ / "Header";
  const std::string original = readBytes(header);
  replaceIn(header, "((0,0,0) (7,7,7) (0,0,0)) ((0,0,0) (15,15,15) (0,0,0))",
            "((0,0,0) (1073741823,7,7) (0,0,0)) ((0,0,0) (1073741823,15,15) (0,0,0))");
  EXPECT_THAT(errorOf(), AllOf(HasSubstr(header.string()),
                               HasSubstr("the level-0 domain (0,0,0)-(1073741823,7,7) spans "
                                         "1073741824 cells along axis x; at most 1073741823")));
  writeFile(header, original);
  replaceIn(header, "((0,0,0) (15,15,15) (0,0,0))", "((0,0,0) (2147483647,15,15) (0,0,0))");
  EXPECT_THAT(errorOf(), HasSubstr("in a level domain box = 2147483647 is outside [-1073741824, "
                                   "1073741824]"));
  writeFile(header, original);
  replaceIn(header, "((0,0,0) (7,7,7) (0,0,0)) ((0,0,0) (15,15,15) (0,0,0))",
            "((-1073741824,0,0) (1073741823,7,7) (0,0,0)) ((0,0,0) (15,15,15) (0,0,0))");
  EXPECT_THAT(errorOf(),
              AllOf(HasSubstr(header.string()),
                    HasSubstr("the level-0 domain (-1073741824,0,0)-(1073741823,7,7) "
                              "spans 2147483648 cells along axis x; at most 1073741823")));
  writeFile(header, original);
  replaceIn(header, "((0,0,0) (7,7,7) (0,0,0)) ((0,0,0) (15,15,15) (0,0,0))",
            "((0,0,0) (7,7,7) (0,0,0)) ((0,0,0) (15,15,17) (0,0,0))");
  EXPECT_THAT(errorOf(), HasSubstr("the level-1 domain (0,0,0)-(15,15,17) is not the level-0 "
                                   "domain (0,0,0)-(7,7,7) refined by 2"));
  // 2^30 grids: their extents are read one by one (3 * 2^30 overflowed an int before).
  writeFile(header, original);
  replaceIn(header, "0 2 0.5\n", "0 1073741824 0.5\n");
  EXPECT_THAT(errorOf(), AllOf(HasSubstr(header.string()),
                               HasSubstr("expected a number (a grid's lower extent)")));
}

TEST_F(AmrexReader, AFabHeaderClaimingFloat32OverFloat64DataIsRefused) {
  const fs::path file = dir_ / "Level_0" / "Cell_D_00000";
  replaceIn(file, kFloat64Little, kFloat32Little);
  const std::string bytes = readBytes(file);
  const std::size_t dataStart = bytes.find('\n') + 1;
  ASSERT_EQ(bytes.size() - dataStart, 512u * 8u);  // 4 x 8 x 8 cells, 2 components, float64
  EXPECT_THAT(errorOf(),
              AllOf(HasSubstr(file.string() + " (FAB at byte 0)"),
                    HasSubstr("the header declares float32 little endian values: 512 x 4 bytes = "
                              "2048 bytes from byte " +
                              std::to_string(dataStart) + ", but the FAB's data runs to byte " +
                              std::to_string(bytes.size()) +
                              " (the end of the file); the declared value type does not match "
                              "the data")));
}

TEST_F(AmrexReader, AFabHeaderClaimingFloat64OverFloat32DataIsRefusedAtTheNextFab) {
  // Level 1's file holds box 1's FAB, then box 0's: box 1's is float32 data declared float64.
  const SynthBox box0{{4, 0, 0}, {7, 7, 7}}, box1{{8, 0, 0}, {11, 7, 7}};
  std::string fab1 = fabBytes(box1, 1, Real::kFloat32Little);
  fab1.replace(fab1.find(kFloat32Little), std::strlen(kFloat32Little), kFloat64Little);
  const std::string fab0 = fabBytes(box0, 1);
  const fs::path file = dir_ / "Level_1" / "Cell_D_00000";
  writeFile(file, fab1 + fab0);
  writeFile(dir_ / "Level_1" / "Cell_H", "1\n1\n2\n0\n(2 0\n" + boxText(box0) + "\n" +
                                             boxText(box1) + "\n)\n2\nFabOnDisk: Cell_D_00000 " +
                                             std::to_string(fab1.size()) +
                                             "\nFabOnDisk: Cell_D_00000 0\n");
  const std::size_t dataStart = fab1.find('\n') + 1;
  ASSERT_EQ(fab1.size() - dataStart, 512u * 4u);
  EXPECT_THAT(errorOf(),
              AllOf(HasSubstr(file.string() + " (FAB at byte 0)"),
                    HasSubstr("declares float64 little endian values: 512 x 8 bytes = "
                              "4096 bytes from byte " +
                              std::to_string(dataStart) + ", but the FAB's data runs to byte " +
                              std::to_string(fab1.size()) + " (where the next FAB starts)")));
}

TEST_F(AmrexReader, NonFiniteValuesNameTheFileTheVariableAndTheCell) {
  const fs::path file = dir_ / "Level_0" / "Cell_D_00000";
  std::string bytes = readBytes(file);
  const std::size_t data = bytes.find('\n') + 1;
  const double nan = std::nan("");
  // Component 1 (B) of cell (1, 2, 3) in the box (0..3, 0..7, 0..7): not under level 1.
  std::memcpy(&bytes[data + 8 * (256 + (3 * 8 + 2) * 4 + 1)], &nan, 8);
  writeFile(file, bytes);
  EXPECT_THAT(errorOf(), HasSubstr(file.string() + ": FAB at byte 0: variable 'B' at level-0 cell "
                                                   "(1, 2, 3) is not a number (nan)"));
}

TEST_F(AmrexReader, DirectoriesFifosAndEscapingPathsAreRefusedByName) {
  const fs::path fab = dir_ / "Level_0" / "Cell_D_00001";
  fs::remove(fab);
  fs::create_directory(fab);
  EXPECT_THAT(errorOf(), HasSubstr(fab.string() + ": is a directory, not a file"));

  const fs::path header = dir_ / "Header";
  const std::string original = readBytes(header);
  replaceIn(header, "Level_0/Cell", "../Level_0/Cell");
  EXPECT_THAT(errorOf(), AllOf(HasSubstr(header.string()),
                               HasSubstr("level path '../Level_0/Cell' leads outside the "
                                         "plotfile")));
  fs::remove(header);
  testing::makeFifo(header);
  EXPECT_THAT(testing::inputErrorWithoutHanging(header, [&] { readAmrexPlotfile(dir_); }),
              HasSubstr(header.string() + ": is a FIFO"));
}

// ---- what the plotfile says about itself ----------------------------------------------------

TEST_F(AmrexReader, TimeFromTheHeaderLevelsCountFromTheCoarsestPeriodicityUnknown) {
  const bricks::AmrField field = readAmrexPlotfile(dir_);
  const DatasetInfo& info = field.info();
  EXPECT_EQ(info.format, "AMReX");
  EXPECT_EQ(info.time, 0.5);  // the synthetic Header's time line
  EXPECT_FALSE(info.periodicKnown);
  EXPECT_EQ(info.lengthUnit, "");
  EXPECT_EQ(info.timeUnit, "");
  EXPECT_EQ(info.fileLevel(0), 1);  // the fine level
  EXPECT_EQ(info.fileLevel(1), 0);
  EXPECT_EQ(info.levelName, "AMReX level (0 = coarsest)");
}

TEST_F(AmrexReader, PeriodicAxesFromJobInfo) {
  writeFile(dir_ / "job_info",
            "==============================================================================\n"
            " Inputs File Parameters\n"
            "==============================================================================\n"
            "amr.n_cell = 8 8 8\n"
            "geometry.is_periodic = 1 0 1\n"
            "geometry.coord_sys = 0\n");
  const DatasetInfo info = readAmrexPlotfile(dir_).info();
  EXPECT_TRUE(info.periodicKnown);
  EXPECT_THAT(info.periodic, ::testing::ElementsAre(true, false, true));
}

TEST_F(AmrexReader, PeriodicAxesFromACodesOwnJobInfo) {
  writeFile(dir_ / "PeleLMeX_job_info", "  geometry.is_periodic = 0 1 1\n");
  const DatasetInfo info = readAmrexPlotfile(dir_).info();
  EXPECT_TRUE(info.periodicKnown);
  EXPECT_THAT(info.periodic, ::testing::ElementsAre(false, true, true));
}

TEST_F(AmrexReader, RejectsAMalformedPeriodicLineNamingJobInfoAndTheLine) {
  writeFile(dir_ / "job_info", "amr.n_cell = 8 8 8\ngeometry.is_periodic = 1 0\n");
  EXPECT_THAT(errorOf(), ::testing::AllOf(HasSubstr((dir_ / "job_info").string() + ":2"),
                                          HasSubstr("geometry.is_periodic")));
  writeFile(dir_ / "job_info", "geometry.is_periodic = 1 2 0\n");
  EXPECT_THAT(errorOf(), HasSubstr((dir_ / "job_info").string() + ":1"));
}

TEST(AmrexInfo, RatiosOtherThanTwoNumberEachLevel) {
  // Three levels with ratios 4 and 4: cell widths 16, 4 and 1 finest cells.
  const DatasetInfo info =
      readAmrexInfo(fs::temp_directory_path() / "no-such-plotfile", 0.0, {4, 2, 0}, 3);
  EXPECT_EQ(info.fileLevel(0), 2);
  EXPECT_EQ(info.fileLevel(2), 1);
  EXPECT_EQ(info.fileLevel(4), 0);
  EXPECT_EQ(info.fileLevel(1), -1);
}

// Oracle: the Header read here: after the variable names and the dimension comes the time.
TEST(AmrexRealData, TimeFromTheHeaderAndNoJobInfo) {
  if (!fs::exists(kRealPlotfile))
    GTEST_SKIP() << "real data " << kRealPlotfile << " is absent (a clone without ../shared/data)";
  std::ifstream header(kRealPlotfile / "Header");
  std::string line;
  std::getline(header, line);  // version
  std::getline(header, line);
  const int variables = std::stoi(line);
  for (int v = 0; v < variables + 1; ++v) std::getline(header, line);  // names, dimension
  std::getline(header, line);
  const double time = std::stod(line);
  EXPECT_NEAR(time, 1.3924e-8, 1e-12);  // README

  bool jobInfo = false;
  for (const auto& entry : fs::directory_iterator(kRealPlotfile))
    jobInfo |= entry.path().filename().string().ends_with("job_info");

  const DatasetInfo info = readAmrexPlotfile(kRealPlotfile).info();
  EXPECT_EQ(info.time, time);
  EXPECT_EQ(info.periodicKnown, jobInfo);
  EXPECT_FALSE(jobInfo) << "the shared plotfile gained a job_info: check its is_periodic here";
  EXPECT_EQ(info.fileLevel(0), 2);  // only the finest level (2) holds leaves
}

TEST(AmrexRealData, ReadsPeleLMeXPlotfile) {
  if (!fs::exists(kRealPlotfile))
    GTEST_SKIP() << "real data " << kRealPlotfile << " is absent (a clone without ../shared/data)";
  const bricks::AmrField field = readAmrexPlotfile(kRealPlotfile);
  ASSERT_EQ(field.cellCount(), 32768u);
  EXPECT_EQ(field.cellsPerLevel(), (std::vector<std::size_t>{32768}));
  ASSERT_EQ(field.channels().size(), 38u);
  EXPECT_EQ(field.channels()[0].name, "x_velocity");
  EXPECT_EQ(field.channels()[37].name, "enstrophy");
  EXPECT_EQ(field.transform().origin, glm::dvec3(0.0));
  for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(field.transform().spacing[a], 0.016 / 32);
  EXPECT_EQ(field.bounds().upper, glm::ivec3(32));

  const auto& vx = field.channel("x_velocity").values;
  const auto& vy = field.channel("y_velocity").values;
  float minY = vy[0], maxY = vy[0], maxAbsX = 0;
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    maxAbsX = std::max(maxAbsX, std::abs(vx[i]));
    minY = std::min(minY, vy[i]);
    maxY = std::max(maxY, vy[i]);
  }
  EXPECT_LT(maxAbsX, 2e-13);
  EXPECT_NEAR(minY, -0.42, 0.01);
  EXPECT_NEAR(maxY, 1.54, 0.01);

  // Independent read of Level_2 box 0, cells (0..7)^3, through its FabOnDisk entry.
  std::ifstream cellH(kRealPlotfile / "Level_2" / "Cell_H");
  std::string word, fabFile;
  long long offset = -1;
  while (cellH >> word)
    if (word == "FabOnDisk:") {
      cellH >> fabFile >> offset;
      break;
    }
  ASSERT_GE(offset, 0);
  std::ifstream fab(kRealPlotfile / "Level_2" / fabFile, std::ios::binary);
  fab.seekg(offset);
  std::string fabHeader;
  std::getline(fab, fabHeader);
  ASSERT_THAT(fabHeader, HasSubstr("((0,0,0) (7,7,7) (0,0,0)) 38"));
  std::vector<double> data(38 * 512);
  fab.read(reinterpret_cast<char*>(data.data()), data.size() * sizeof(double));
  ASSERT_TRUE(fab);
  std::map<std::tuple<int, int, int>, std::size_t> index;
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const glm::ivec3 p = field.lowers()[i];
    index[{p.x, p.y, p.z}] = i;
  }
  for (int n : {0, 1, 77, 300, 511})
    for (int c : {1, 2, 5, 37}) {
      const glm::ivec3 cell(n % 8, n / 8 % 8, n / 64);
      const std::size_t i = index.at({cell.x, cell.y, cell.z});
      EXPECT_EQ(field.channels()[c].values[i], float(data[c * 512 + n])) << n << ' ' << c;
    }
}

}  // namespace
}  // namespace amrstream::formats
