// Gerris text leaf dumps: the real vortex-ring dump and small files with known fields read back
// cell by cell; malformed files are rejected naming the file and the line.

#include "formats/gerris/gerris_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "amrstream/error.hpp"
#include "input_error_of.hpp"
#include "special_files.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

const fs::path kRealFile = fs::path(AMRSTREAM_REAL_DATA_DIR) / "gerris-ring" / "ring-end.txt";

std::map<std::tuple<int, int, int, int>, std::size_t> indexCells(const bricks::AmrField& field) {
  std::map<std::tuple<int, int, int, int>, std::size_t> index;
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const glm::ivec3 p = field.lowers()[i];
    index[{p.x, p.y, p.z, field.levels()[i]}] = i;
  }
  return index;
}

double cellVolume(const bricks::AmrField& field, std::size_t i) {
  const glm::dvec3 size = field.transform().spacing * double(field.cellWidth(field.levels()[i]));
  return size.x * size.y * size.z;
}

class GerrisReader : public testing::TempDirTest {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }
};

// Analytic fields of a cell centre.
double fieldA(glm::dvec3 c) { return 1.0 + 2.0 * c.x - 3.0 * c.y + 0.5 * c.z; }
double fieldB(glm::dvec3 c) { return c.x * c.y - c.z; }

// Unit box: level 1 everywhere except the (-,-,-) octant, refined to level 2.
std::string twoLevelDump(std::vector<glm::dvec3>* centres, std::vector<int>* levels) {
  std::ostringstream out;
  out.precision(9);
  out << "# 1:x 2:y 3:z 4:A 5:B 6:Lev 0.25\n";
  auto emit = [&](glm::dvec3 c, int level) {
    out << c.x << ' ' << c.y << ' ' << c.z << ' ' << fieldA(c) << ' ' << fieldB(c) << ' ' << level
        << '\n';
    centres->push_back(c);
    levels->push_back(level);
  };
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        const glm::dvec3 c = glm::dvec3(i, j, k) * 0.5 - 0.25;
        if (i + j + k == 0) {
          for (int n = 0; n < 8; ++n)
            emit(glm::dvec3(n & 1, (n >> 1) & 1, n >> 2) * 0.25 - 0.375, 2);
        } else {
          emit(c, 1);
        }
      }
  return out.str();
}

TEST_F(GerrisReader, ReadsTwoLevelLayoutWithAnalyticValues) {
  std::vector<glm::dvec3> centres;
  std::vector<int> levels;
  const bricks::AmrField field = readGerris(write("two.txt", twoLevelDump(&centres, &levels)));
  ASSERT_EQ(field.cellCount(), 15u);
  ASSERT_EQ(field.channels().size(), 2u);
  EXPECT_EQ(field.channels()[0].name, "A");
  EXPECT_EQ(field.channels()[1].name, "B");
  EXPECT_EQ(field.transform().origin, glm::dvec3(-0.5));
  EXPECT_EQ(field.transform().spacing, glm::dvec3(0.25));
  EXPECT_EQ(field.cellsPerLevel(), (std::vector<std::size_t>{8, 7}));
  double volume = 0.0;
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    const int width = field.cellWidth(field.levels()[i]);
    EXPECT_EQ(field.levels()[i], 2 - levels[i]) << i;
    const glm::dvec3 centre =
        field.transform().toPhysical(glm::dvec3(field.lowers()[i]) + 0.5 * width);
    EXPECT_EQ(centre, centres[i]) << i;
    EXPECT_FLOAT_EQ(field.channels()[0].values[i], float(fieldA(centres[i]))) << i;
    EXPECT_FLOAT_EQ(field.channels()[1].values[i], float(fieldB(centres[i]))) << i;
    volume += cellVolume(field, i);
  }
  EXPECT_DOUBLE_EQ(volume, 1.0);
}

TEST_F(GerrisReader, AcceptsOtherColumnOrdersAndNames) {
  const bricks::AmrField field = readGerris(write("cols.txt",
                                                  "# 1:Lev 2:P 3:z 4:y 5:x 6:T 1.5\n"
                                                  "0 7 0 0 0 -2\n"
                                                  "0 8 0 0 1 -3\n"));
  ASSERT_EQ(field.cellCount(), 2u);
  ASSERT_EQ(field.channels().size(), 2u);
  EXPECT_EQ(field.channels()[0].name, "P");
  EXPECT_EQ(field.channels()[1].name, "T");
  EXPECT_EQ(field.transform().origin, glm::dvec3(-0.5));
  EXPECT_EQ(field.lowers()[1], glm::ivec3(1, 0, 0));
  EXPECT_EQ(field.channels()[0].values[1], 8.0f);
  EXPECT_EQ(field.channels()[1].values[1], -3.0f);
}

TEST_F(GerrisReader, RejectsMalformedFiles) {
  struct Case {
    const char* name;
    std::string text;
    std::vector<std::string> expected;
  };
  const std::string header = "# 1:x 2:y 3:z 4:U 5:Lev 0\n";
  const std::vector<Case> cases = {
      {"empty.txt", "", {"empty"}},
      {"noheader.txt", "0.25 0.25 0.25 1 1\n", {":1", "header"}},
      {"garbled.txt", "# 1:x 2y 3:z 4:U 5:Lev 0\n", {":1", "garbled", "2y"}},
      {"numbering.txt", "# 1:x 3:y 3:z 4:U 5:Lev 0\n", {":1", "3:y"}},
      {"nolevel.txt", "# 1:x 2:y 3:z 4:U 0\n0 0 0 1\n", {":1", "Lev"}},
      {"short.txt", header + "0.25 0.25 0.25 1 1\n0.25 0.25 1 1\n", {":3", "4 columns", "5"}},
      {"long.txt", header + "0.25 0.25 0.25 1 1 7\n", {":2", "6 columns"}},
      {"nonnumeric.txt",
       header + "0.25 0.25 0.25 1 1\n-0.25 0.25 0.25 abc 1\n",
       {":3", "'U'", "abc"}},
      {"offlattice.txt",
       header + "0.25 0.25 0.25 1 1\n-0.25 0.2 0.25 1 1\n",
       {":3", "y = 0.2", "lattice"}},
      {"negative.txt", header + "0.25 0.25 0.25 1 -1\n", {":2", "level -1"}},
      {"fraction.txt", header + "0.25 0.25 0.25 1 1.5\n", {":2", "level 1.5"}},
      {"absurd.txt", header + "0.25 0.25 0.25 1 99\n", {":2", "level 99"}},
      {"overlap.txt", header + "0.25 0.25 0.25 1 1\n0.125 0.125 0.125 1 2\n", {"overlap.txt"}},
      {"nocells.txt", header, {"no cells"}},
  };
  for (const Case& c : cases) {
    const fs::path path = write(c.name, c.text);
    const std::string error = testing::inputErrorOf([&] { readGerris(path); });
    EXPECT_THAT(error, HasSubstr(path.string())) << c.name;
    for (const std::string& part : c.expected) EXPECT_THAT(error, HasSubstr(part)) << c.name;
  }
  EXPECT_THAT(testing::inputErrorOf([&] { readGerris(dir_ / "missing.txt"); }),
              HasSubstr("missing.txt"));
}

TEST_F(GerrisReader, SparseFilesAndEndlessLinesAreRefusedBeforeTheyAreHeld) {
  const std::string header = "# 1:x 2:y 3:z 4:U 5:Lev 0\n";
  const fs::path sparse = dir_ / "sparse.txt";
  if (testing::makeSparseFile(sparse, header + "0.25 0.25 0.25 1 1\n", std::uintmax_t(3) << 30)) {
    EXPECT_THAT(testing::inputErrorOf([&] { readGerris(sparse); }),
                HasSubstr(sparse.string() + ": the Gerris file has a hole from byte"));
  }
  const fs::path endless = write("endless.txt", header + std::string(std::size_t(3) << 20, '1'));
  EXPECT_THAT(testing::inputErrorOf([&] { readGerris(endless); }),
              HasSubstr(endless.string() + ":2: the line is longer than 1048576 bytes"));
}

// ---- what the dump says about itself --------------------------------------------------------

TEST_F(GerrisReader, ValuesThatAreNotFiniteFloatsNameTheLineAndTheColumn) {
  const std::string header = "# 1:x 2:y 3:z 4:U 5:P 6:Lev 0\n";
  const std::string first = "0 0 0 1 2 0\n";
  EXPECT_THAT(testing::inputErrorOf(
                  [&] { readGerris(write("nan.txt", header + first + "1 0 0 nan 2 0\n")); }),
              HasSubstr((dir_ / "nan.txt").string() + ":3: column 'U' is not a number: 'nan'"));
  EXPECT_THAT(testing::inputErrorOf(
                  [&] { readGerris(write("inf.txt", header + first + "1 0 0 1 -inf 0\n")); }),
              HasSubstr(":3: column 'P' is infinite: '-inf'"));
  EXPECT_THAT(testing::inputErrorOf(
                  [&] { readGerris(write("huge.txt", header + first + "1 0 0 1e300 2 0\n")); }),
              HasSubstr(":3: column 'U' is beyond the float range: '1e300'"));
}

TEST_F(GerrisReader, DirectoriesAndFifosAreRefusedByNameBeforeOpening) {
  fs::create_directory(dir_ / "dump");
  EXPECT_THAT(testing::inputErrorOf([&] { readGerris(dir_ / "dump"); }),
              HasSubstr((dir_ / "dump").string() + ": is a directory, not a file"));
  testing::makeFifo(dir_ / "fifo.txt");
  EXPECT_THAT(
      testing::inputErrorWithoutHanging(dir_ / "fifo.txt", [&] { readGerris(dir_ / "fifo.txt"); }),
      HasSubstr((dir_ / "fifo.txt").string() + ": is a FIFO"));
  EXPECT_THAT(testing::inputErrorWithoutHanging(dir_ / "fifo.txt",
                                                [&] { readGerrisTime(dir_ / "fifo.txt"); }),
              HasSubstr((dir_ / "fifo.txt").string() + ": is a FIFO"));
}

TEST_F(GerrisReader, TimeIsTheHeadersLastNumberAndLevelsAreGerrisLevels) {
  std::vector<glm::dvec3> centres;
  std::vector<int> levels;
  const DatasetInfo info = readGerris(write("two.txt", twoLevelDump(&centres, &levels))).info();
  EXPECT_EQ(info.format, "Gerris");
  EXPECT_EQ(info.time, 0.25);       // the header ends with 0.25
  EXPECT_EQ(info.fileLevel(0), 2);  // the dump's Lev 2 cells are the finest
  EXPECT_EQ(info.fileLevel(1), 1);
  EXPECT_FALSE(info.periodicKnown);
  EXPECT_EQ(info.lengthUnit, "");
  EXPECT_EQ(info.timeUnit, "");
}

TEST_F(GerrisReader, HeaderWithoutATimeLeavesItUnknown) {
  const fs::path path = write("untimed.txt", "# 1:x 2:y 3:z 4:U 5:Lev\n0.25 0.25 0.25 1 1\n");
  EXPECT_FALSE(readGerris(path).info().time.has_value());
}

// The header's last word, read here independently of the reader.
double headerTime(const fs::path& file) {
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  return std::stod(header.substr(header.find_last_of(' ') + 1));
}

TEST(GerrisRealData, RingDumpTimeAndLevels) {
  if (!fs::exists(kRealFile))
    GTEST_SKIP() << "real data " << kRealFile << " is absent (a clone without ../shared/data)";
  const bricks::AmrField field = readGerris(kRealFile);
  EXPECT_EQ(field.info().time, headerTime(kRealFile));
  EXPECT_EQ(field.info().time, 1.0);        // ring.gfs runs to TEND = 1.0 and dumps at the end
  EXPECT_EQ(field.info().fileLevel(0), 7);  // README: octree levels 3..7
  EXPECT_EQ(field.info().fileLevel(field.coarsestLevel()), 3);
}

TEST(GerrisRealData, SeriesSnapshotTimeMatchesItsName) {
  const fs::path archive = kRealFile.parent_path().parent_path() / "gerris-ring-series.tar.xz";
  if (!fs::exists(archive))
    GTEST_SKIP() << "real data " << archive << " is absent (a clone without ../shared/data)";
  const fs::path dir = fs::temp_directory_path() / "amrstream-gerris-series-time";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string command = "tar -xJf '" + archive.string() + "' -C '" + dir.string() +
                              "' gerris-ring-series/ring-0.020.txt";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const fs::path snapshot = dir / "gerris-ring-series" / "ring-0.020.txt";
  const auto time = readGerris(snapshot).info().time;
  EXPECT_EQ(time, headerTime(snapshot));
  EXPECT_EQ(time, 0.02);  // named ring-%05.3f.txt after its time
  fs::remove_all(dir);
}

TEST(GerrisRealData, ReadsVortexRingDump) {
  if (!fs::exists(kRealFile))
    GTEST_SKIP() << "real data " << kRealFile << " is absent (a clone without ../shared/data)";
  const bricks::AmrField field = readGerris(kRealFile);
  ASSERT_EQ(field.cellCount(), 69441u);
  // Gerris levels 7, 6, 5, 4, 3 are our levels 0..4.
  EXPECT_EQ(field.cellsPerLevel(), (std::vector<std::size_t>{59144, 6519, 2413, 1049, 316}));
  ASSERT_EQ(field.channels().size(), 3u);
  EXPECT_EQ(field.channels()[0].name, "U");
  EXPECT_EQ(field.channels()[1].name, "V");
  EXPECT_EQ(field.channels()[2].name, "W");
  EXPECT_EQ(field.transform().origin, glm::dvec3(-0.5));
  EXPECT_EQ(field.transform().spacing, glm::dvec3(1.0 / 128));
  EXPECT_EQ(field.bounds().lower, glm::ivec3(0));
  EXPECT_EQ(field.bounds().upper, glm::ivec3(128));

  double volume = 0.0, maxSpeed = 0.0;
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    volume += cellVolume(field, i);
    const glm::dvec3 u(field.channels()[0].values[i], field.channels()[1].values[i],
                       field.channels()[2].values[i]);
    maxSpeed = std::max(maxSpeed, glm::length(u));
  }
  EXPECT_DOUBLE_EQ(volume, 1.0);
  EXPECT_NEAR(maxSpeed, 0.354, 0.001);

  // Independently parse a few lines and find their cells.
  const auto index = indexCells(field);
  std::ifstream in(kRealFile);
  std::string line;
  std::getline(in, line);
  int checked = 0;
  for (int number = 2; std::getline(in, line); ++number) {
    if (number % 9973 != 2) continue;
    std::istringstream words(line);
    glm::dvec3 c, u;
    int lev;
    ASSERT_TRUE(words >> c.x >> c.y >> c.z >> u.x >> u.y >> u.z >> lev) << line;
    const int width = 1 << (7 - lev);
    const glm::ivec3 lower((c + 0.5) * 128.0 - 0.5 * width + 0.5);  // +0.5: round, all >= 0
    const auto found = index.find({lower.x, lower.y, lower.z, 7 - lev});
    ASSERT_NE(found, index.end()) << "line " << number << ": " << line;
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(field.channels()[a].values[found->second], float(u[a])) << "line " << number;
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

}  // namespace
}  // namespace amrstream::formats
