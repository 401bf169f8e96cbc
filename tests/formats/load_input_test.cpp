// Format detection by content and extension, on small files the test writes; what the builtin
// datasets say about themselves.

#include "formats/load_input.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>

#include "input_error_of.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

class DetectFormat : public testing::TempDirTest {
 protected:
  std::string write(const std::string& name, const std::string& bytes) {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return (dir_ / name).string();
  }
};

TEST_F(DetectFormat, RecognisesEveryFormat) {
  EXPECT_EQ(detectFormat("builtin:cloud"), Format::Builtin);
  EXPECT_EQ(detectFormat(write("a.exa", "cells a.cells\n")), Format::ExaBricks);
  write("plt/Header", "HyperCLaw-V1.1\n38\n");
  EXPECT_EQ(detectFormat((dir_ / "plt").string()), Format::Amrex);
  EXPECT_EQ(
      detectFormat(write("flash_hdf5_plt_cnt_0001", std::string("\x89HDF\r\n\x1a\n", 8) + "x")),
      Format::Flash);
  const std::string enzo = write("DD0001/data0001", "InitialTime = 0\n");
  write("DD0001/data0001.hierarchy", "Grid = 1\n");
  EXPECT_EQ(detectFormat(enzo), Format::Enzo);
  EXPECT_EQ(detectFormat(enzo + ".hierarchy"), Format::Enzo);
  EXPECT_EQ(detectFormat(write("DD0001/data0001.cpu0000", std::string("\x89HDF\r\n\x1a\n", 8))),
            Format::Enzo);
  EXPECT_EQ(detectFormat(write("ring.txt", "# 1:x 2:y 3:z 4:U 5:V 6:W 7:Lev 1\n")), Format::Gerris);
}

TEST_F(DetectFormat, NamesTheInputWhenItIsNotRecognised) {
  EXPECT_THAT(testing::inputErrorOf([&] { detectFormat((dir_ / "missing").string()); }),
              HasSubstr("missing: no such file"));
  EXPECT_THAT(testing::inputErrorOf([&] { detectFormat(write("notes.txt", "hello\n")); }),
              HasSubstr("notes.txt: unknown input format"));
  fs::create_directories(dir_ / "empty");
  EXPECT_THAT(testing::inputErrorOf([&] { detectFormat((dir_ / "empty").string()); }),
              HasSubstr("not an AMReX plotfile"));
}

// ABC is sin/cos of 2 pi x, y, z over the unit cube: one full period on every axis.
TEST(BuiltinInfo, AbcIsPeriodicTheOthersAreNot) {
  synth::GeneratorOptions small;
  small.levels = 3;
  small.rootBlocks = 1;
  small.targetCells = 5000;
  const bricks::DatasetInfo abc = loadInput("builtin:abc", small).info();
  EXPECT_EQ(abc.format, "builtin");
  EXPECT_EQ(abc.time, 0.0);
  EXPECT_TRUE(abc.periodicKnown);
  EXPECT_EQ(abc.periodic, (std::array<bool, 3>{true, true, true}));
  for (const char* kind : {"builtin:rotation", "builtin:cloud"}) {
    const bricks::DatasetInfo info = loadInput(kind, small).info();
    EXPECT_TRUE(info.periodicKnown) << kind;
    EXPECT_EQ(info.periodic, (std::array<bool, 3>{false, false, false})) << kind;
  }
  // Generator levels count from the root blocks: level 0 is the coarsest of the 3.
  EXPECT_EQ(abc.fileLevel(2), 0);
  EXPECT_EQ(abc.fileLevel(0), 2);
}

}  // namespace
}  // namespace amrstream::formats
