// Snapshot times read from metadata alone: on every real dataset they equal the time the full
// reader gives; a real Gerris series expands from its glob pattern in time order; small written
// files check the header-only reads, the absent times and the errors, and the pattern expansion's
// duplicates, directories and order.

#include "formats/snapshot_time.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "formats/exa/exa_format.hpp"
#include "formats/load_input.hpp"
#include "input_error_of.hpp"
#include "synth/generators.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::inputErrorOf;
namespace fs = std::filesystem;

const fs::path kRealDataDir(AMRSTREAM_REAL_DATA_DIR);

// The time the full reader gives, the oracle for snapshotTime.
std::optional<double> readerTime(const fs::path& input) {
  return loadInput(input.string(), {}).info().time;
}

// The header's last word, read here independently of the Gerris reader.
double gerrisHeaderTime(const fs::path& file) {
  std::ifstream in(file);
  std::string header;
  std::getline(in, header);
  return std::stod(header.substr(header.find_last_of(' ') + 1));
}

// The AMReX Header's time line (after the version, the variable count, the names and the
// dimension), read here independently of the AMReX reader.
double amrexHeaderTime(const fs::path& plotfile) {
  std::ifstream in(plotfile / "Header");
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  const int variables = std::stoi(line);
  for (int skipped = 0; skipped <= variables; ++skipped) std::getline(in, line);
  std::getline(in, line);
  return std::stod(line);
}

std::string absent(const fs::path& realData) {
  return "real data " + realData.string() + " is absent (a clone without ../shared/data)";
}

TEST(SnapshotTimeReal, EnzoParameterFileAndItsSiblingsGiveTheReadersTime) {
  const fs::path parameters = kRealDataDir / "enzo-moving7" / "DD0010" / "moving7_0010";
  if (!fs::exists(parameters)) GTEST_SKIP() << absent(parameters);
  const auto time = readerTime(parameters);
  ASSERT_TRUE(time.has_value());
  EXPECT_EQ(*time, 0.81751317119117);  // the parameter file's InitialTime
  EXPECT_EQ(snapshotTime(parameters.string()), time);
  for (const char* sibling : {".hierarchy", ".harrays"}) {
    const fs::path path = parameters.string() + sibling;
    EXPECT_EQ(snapshotTime(path.string()), time) << path;
    EXPECT_EQ(snapshotTime(path.string()), readerTime(path)) << path;
  }
}

// A glob over an Enzo output directory matches the parameter file and every file named after
// it, readable or not (.boundary, .procmap): all stand for the one dataset.
TEST(SnapshotTimeReal, EveryFileOfAnEnzoDatasetStandsForItsParameterFile) {
  const fs::path parameters = kRealDataDir / "enzo-moving7" / "DD0010" / "moving7_0010";
  if (!fs::exists(parameters)) GTEST_SKIP() << absent(parameters);
  const std::vector<std::string> files =
      expandSnapshotPatterns(std::vector<std::string>{parameters.string() + "*"});
  ASSERT_EQ(files.size(), 7u);  // the parameter file, .boundary, .boundary.hdf, .cpu0000, ...
  for (const std::string& file : files) EXPECT_EQ(snapshotDataset(file), parameters.string());
  const fs::path gerris = kRealDataDir / "gerris-ring" / "ring-end.txt";
  EXPECT_EQ(snapshotDataset(gerris.string()), gerris.string());
  EXPECT_EQ(snapshotDataset("builtin:abc"), "builtin:abc");
}

TEST(SnapshotTimeReal, AmrexPlotfileGivesTheReadersTime) {
  const fs::path plotfile = kRealDataDir / "amrex-pelelmex-3d" / "example_plt_3d";
  if (!fs::exists(plotfile)) GTEST_SKIP() << absent(plotfile);
  const auto time = readerTime(plotfile);
  ASSERT_TRUE(time.has_value());
  EXPECT_EQ(*time, amrexHeaderTime(plotfile));
  EXPECT_NEAR(*time, 1.3924e-8, 1e-12);  // README
  EXPECT_EQ(snapshotTime(plotfile.string()), time);
}

// The 2D file loads (as a slab); h5dump gives its `real scalars` time 1.0000117238534479e-09.
TEST(SnapshotTimeReal, Flash2dPlotfileGivesTheReadersTime) {
  const fs::path file = kRealDataDir / "flash-2d-nanowire" / "nanowire_arrayhdf5_plt_cnt_0100";
  if (!fs::exists(file)) GTEST_SKIP() << absent(file);
  const auto time = readerTime(file);
  EXPECT_EQ(time, 1.0000117238534479e-09);
  EXPECT_EQ(snapshotTime(file.string()), time);
}

TEST(SnapshotTimeReal, GerrisDumpGivesTheReadersTime) {
  const fs::path file = kRealDataDir / "gerris-ring" / "ring-end.txt";
  if (!fs::exists(file)) GTEST_SKIP() << absent(file);
  const auto time = readerTime(file);
  EXPECT_EQ(time, gerrisHeaderTime(file));
  EXPECT_EQ(snapshotTime(file.string()), time);
}

class SnapshotTime : public testing::TempDirTest {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return path;
  }

  static bricks::AmrField smallField(std::optional<double> time) {
    bricks::AmrField field =
        synth::generate("rotation", {.levels = 2, .rootBlocks = 1, .targetCells = 600});
    DatasetInfo info = field.info();
    info.time = time;
    field.setInfo(info);
    return field;
  }

  // Writes DIRECTORY/snapshot.exa and removes its cells and scalars files: a time read from it
  // comes from the config alone.
  fs::path writeExaConfigOnly(const std::string& directory, std::optional<double> time) {
    fs::create_directories(dir_ / directory);
    const fs::path exa = writeExa(smallField(time), dir_ / directory / "snapshot");
    for (const auto& entry : fs::directory_iterator(dir_ / directory))
      if (entry.path() != exa) fs::remove(entry.path());
    return exa;
  }

  std::vector<std::string> expand(const std::vector<std::string>& patterns) {
    return expandSnapshotPatterns(patterns);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
};

TEST_F(SnapshotTime, RealGerrisSeriesExpandsInTimeOrder) {
  const fs::path archive = kRealDataDir / "gerris-ring-series.tar.xz";
  if (!fs::exists(archive)) GTEST_SKIP() << absent(archive);
  const std::string command = "tar -xJf '" + archive.string() + "' -C '" + dir_.string() + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;

  const std::vector<std::string> snapshots = expand({path("gerris-ring-series/ring-*.txt")});
  ASSERT_EQ(snapshots.size(), 31u);
  for (std::size_t i = 0; i < snapshots.size(); ++i) {
    const auto time = snapshotTime(snapshots[i]);
    ASSERT_TRUE(time.has_value()) << snapshots[i];
    EXPECT_NEAR(*time, 0.02 * double(i), 1e-9) << snapshots[i];
    EXPECT_EQ(*time, gerrisHeaderTime(snapshots[i])) << snapshots[i];
  }
}

TEST_F(SnapshotTime, ExaTimeComesFromTheConfigAlone) {
  const fs::path exa = writeExa(smallField(0.375), dir_ / "timed");
  EXPECT_EQ(readerTime(exa), 0.375);
  const fs::path configOnly = writeExaConfigOnly("alone", 0.375);
  ASSERT_FALSE(fs::exists(dir_ / "alone" / "snapshot.cells"));
  EXPECT_EQ(snapshotTime(configOnly.string()), 0.375);
}

TEST_F(SnapshotTime, ExaWithoutATimeLineHasNone) {
  const fs::path exa = writeExa(smallField(std::nullopt), dir_ / "untimed");
  EXPECT_EQ(readerTime(exa), std::nullopt);
  EXPECT_EQ(snapshotTime(exa.string()), std::nullopt);
}

TEST_F(SnapshotTime, GerrisTimeComesFromTheHeaderAlone) {
  // Rows the reader would reject: only the header is read.
  const fs::path file = write("ring.txt", "# 1:x 2:y 3:z 4:U 5:Lev 0.125\nnot a row\n");
  EXPECT_EQ(snapshotTime(file.string()), 0.125);
}

TEST_F(SnapshotTime, GerrisHeaderWithoutATimeHasNone) {
  const fs::path file = write("untimed.txt", "# 1:x 2:y 3:z 4:U 5:Lev\n0.25 0.25 0.25 1 1\n");
  EXPECT_EQ(readerTime(file), std::nullopt);
  EXPECT_EQ(snapshotTime(file.string()), std::nullopt);
}

TEST_F(SnapshotTime, EnzoWithoutAParameterFileHasNoTime) {
  const fs::path hierarchy = write("DD0001/data0001.hierarchy", "Grid = 1\n");
  EXPECT_EQ(snapshotTime(hierarchy.string()), std::nullopt);
}

TEST_F(SnapshotTime, BuiltinDatasetsAreAtTimeZero) {
  EXPECT_EQ(snapshotTime("builtin:rotation"), 0.0);
  EXPECT_EQ(
      synth::generate("rotation", {.levels = 1, .rootBlocks = 1, .targetCells = 512}).info().time,
      0.0);
  EXPECT_THAT(inputErrorOf([] { snapshotTime("builtin:nope"); }),
              HasSubstr("builtin:nope: unknown generator kind 'nope'"));
}

TEST_F(SnapshotTime, ErrorsNameTheFileAndTheProblem) {
  const std::string missing = path("missing.txt");
  EXPECT_THAT(inputErrorOf([&] { snapshotTime(missing); }), HasSubstr(missing + ": no such file"));

  const std::string unknown = write("notes.txt", "plain text\n").string();
  EXPECT_THAT(inputErrorOf([&] { snapshotTime(unknown); }),
              HasSubstr(unknown + ": format not recognised"));

  // The header's last word is neither a column N:NAME nor a number.
  const std::string gerris = write("bad.txt", "# 1:x 2:y 3:z 4:U 5:Lev t=0.5\n").string();
  EXPECT_THAT(inputErrorOf([&] { snapshotTime(gerris); }),
              HasSubstr(gerris + ":1: garbled header column 't=0.5'"));

  const std::string exa = write("bad.exa", "cells bad.cells\ntime abc\n").string();
  EXPECT_THAT(inputErrorOf([&] { snapshotTime(exa); }),
              HasSubstr(exa + ":2: 'time' needs one finite number, got 'abc'"));

  const std::string enzo = write("DD0002/data0002", "InitialTime = soon\n").string();
  write("DD0002/data0002.hierarchy", "Grid = 1\n");
  EXPECT_THAT(inputErrorOf([&] { snapshotTime(enzo); }),
              HasSubstr(enzo + ": InitialTime is not a number: 'soon'"));

  const std::string plotfile = path("plt");
  write("plt/Header", "HyperCLaw-V1.1\n1\nu\n3\nlater\n");
  EXPECT_THAT(inputErrorOf([&] { snapshotTime(plotfile); }),
              HasSubstr(plotfile + "/Header: expected a number (the time)"));
}

TEST_F(SnapshotTime, PatternsExpandInSortedOrderAcrossDirectories) {
  for (const char* name :
       {"DD0002/data_0002", "DD0001/data_0001", "DD0001/data_0001.hierarchy", "other/data_0003"})
    write(name, "");
  EXPECT_THAT(expand({path("DD*/data_*")}),
              ElementsAre(path("DD0001/data_0001"), path("DD0001/data_0001.hierarchy"),
                          path("DD0002/data_0002")));
  EXPECT_THAT(expand({path("DD*/data_????")}),
              ElementsAre(path("DD0001/data_0001"), path("DD0002/data_0002")));
}

TEST_F(SnapshotTime, PathsAndBuiltinsAreKeptInTheOrderGiven) {
  write("b.txt", "");
  write("a.txt", "");
  write("plt/Header", "");
  EXPECT_THAT(expand({path("b.txt"), path("plt"), "builtin:abc", path("*.txt")}),
              ElementsAre(path("b.txt"), path("plt"), "builtin:abc", path("a.txt")));
}

TEST_F(SnapshotTime, DuplicatesAreDroppedKeepingTheFirst) {
  write("a.txt", "");
  write("b.txt", "");
  write("plt/Header", "");
  EXPECT_THAT(expand({path("plt/"), path("b.txt"), path("*.txt"), path("./a.txt"), path("plt"),
                      path("b.txt")}),
              ElementsAre(path("plt/"), path("b.txt"), path("a.txt")));
}

TEST_F(SnapshotTime, PatternMatchingNothingIsAnError) {
  write("a.txt", "");
  const std::string pattern = path("ring-*.txt");
  EXPECT_EQ(inputErrorOf([&] { expand({path("a.txt"), pattern}); }), pattern + ": matches no file");
}

}  // namespace
}  // namespace amrstream::formats
