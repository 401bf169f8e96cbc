// Format detection by content and extension, on small files the test writes; what the builtin
// datasets say about themselves.

#include "formats/load_input.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "formats/enzo/enzo_reader.hpp"
#include "input_error_of.hpp"
#include "special_files.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

class DetectFormat : public testing::TempDirTest {
 protected:
  std::string write(const std::string& name, const std::string& bytes) {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return (dir_ / name).string();
  }
  // An HDF5 file holding one small integer dataset per name.
  std::string writeHdf5(const std::string& name, const std::vector<std::string>& datasets) {
    const fs::path path = dir_ / name;
    fs::create_directories(path.parent_path());
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(file, 0);
    const hsize_t dims[1] = {2};
    const int values[2] = {1, 2};
    for (const std::string& dataset : datasets) {
      const hid_t space = H5Screate_simple(1, dims, nullptr);
      const hid_t set = H5Dcreate2(file, dataset.c_str(), H5T_NATIVE_INT, space, H5P_DEFAULT,
                                   H5P_DEFAULT, H5P_DEFAULT);
      EXPECT_GE(H5Dwrite(set, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values), 0);
      H5Dclose(set);
      H5Sclose(space);
    }
    H5Fclose(file);
    return path.string();
  }
};

TEST_F(DetectFormat, RecognisesEveryFormat) {
  EXPECT_EQ(detectFormat("builtin:cloud"), Format::Builtin);
  EXPECT_EQ(detectFormat(write("a.exa", "cells a.cells\n")), Format::ExaBricks);
  write("plt/Header", "HyperCLaw-V1.1\n38\n");
  EXPECT_EQ(detectFormat((dir_ / "plt").string()), Format::Amrex);
  EXPECT_EQ(detectFormat(writeHdf5("flash_hdf5_plt_cnt_0001", {"unknown names", "refine level"})),
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
              HasSubstr("notes.txt: format not recognised: no known extension or signature; "
                        "amrstream reads builtin:KIND, a .exa, an AMReX plotfile folder, an Enzo "
                        "parameter file (or a file beside it), FLASH HDF5 and a Gerris text "
                        "dump"));
  fs::create_directories(dir_ / "empty");
  EXPECT_THAT(testing::inputErrorOf([&] { detectFormat((dir_ / "empty").string()); }),
              HasSubstr("not an AMReX plotfile"));
}

// Paths that are not a dataset but lead to one say which to pass: an Enzo output folder its
// parameter file, an AMReX Header its plotfile folder; the files Enzo writes beside its
// .hierarchy (.boundary, .boundary.hdf, .procmap) stand for their dataset.
TEST_F(DetectFormat, PathsBesideADatasetLeadToIt) {
  const std::string enzo = write("DD0001/data0001", "InitialTime = 0\n");
  write("DD0001/data0001.hierarchy", "Grid = 1\n");
  EXPECT_THAT(testing::inputErrorOf([&] { detectFormat((dir_ / "DD0001").string()); }),
              HasSubstr("DD0001: an Enzo output folder: pass its parameter file, " + enzo));
  for (const std::string companion : {".boundary", ".boundary.hdf", ".procmap"}) {
    const std::string file = write("DD0001/data0001" + companion, "x");
    EXPECT_EQ(detectFormat(file), Format::Enzo) << companion;
    EXPECT_EQ(enzoParameterFile(file), fs::path(enzo)) << companion;
  }
  const std::string header = write("plt/Header", "HyperCLaw-V1.1\n38\n");
  EXPECT_THAT(testing::inputErrorOf([&] { detectFormat(header); }),
              HasSubstr(header + ": an AMReX plotfile's Header: pass the plotfile's folder, " +
                        (dir_ / "plt").string()));
}

// Only FLASH files are HDF5 files with 'unknown names': any other HDF5 file is not taken for one.
TEST_F(DetectFormat, AnUnknownHdf5FileIsNotTakenForFlash) {
  const std::string chombo = writeHdf5("chombo.hdf5", {"level_0_boxes", "level_0_data"});
  const std::string boundary =
      writeHdf5("DD0010/moving7_0010.boundary.hdf", {"BoundaryDimension", "BoundaryValue"});
  for (const std::string& input : {chombo, boundary})
    EXPECT_THAT(testing::inputErrorOf([&] { detectFormat(input); }),
                AllOf(HasSubstr(input + ": format not recognised: an HDF5 file without FLASH's "
                                        "'unknown names' dataset; amrstream reads builtin:KIND"),
                      HasSubstr("Enzo"), HasSubstr("AMReX"), HasSubstr("Gerris")))
        << input;
  const std::string corrupt =
      write("corrupt_hdf5_plt_cnt_0001", std::string("\x89HDF\r\n\x1a\n", 8) + "x");
  EXPECT_THAT(testing::inputErrorOf([&] { detectFormat(corrupt); }),
              HasSubstr(corrupt + ": an HDF5 file that HDF5 cannot open (truncated or corrupt?)"));
}

TEST_F(DetectFormat, AFifoIsRefusedByNameBeforeItIsOpened) {
  const fs::path fifo = dir_ / "input.fifo";
  testing::makeFifo(fifo);
  EXPECT_THAT(testing::inputErrorWithoutHanging(fifo, [&] { detectFormat(fifo.string()); }),
              HasSubstr(fifo.string() + ": is a FIFO (named pipe), not a regular file"));
  fs::create_directories(dir_ / "plt");
  testing::makeFifo(dir_ / "plt" / "Header");
  EXPECT_THAT(testing::inputErrorWithoutHanging(dir_ / "plt" / "Header",
                                                [&] { detectFormat((dir_ / "plt").string()); }),
              HasSubstr("not an AMReX plotfile"));
}

// ABC is sin/cos of 2 pi x, y, z over the unit cube: one full period on every axis.
TEST(BuiltinInfo, AbcIsPeriodicTheOthersAreNot) {
  BuiltinOptions small;
  small.levels = 3;
  small.rootBlocks = 1;
  small.targetCells = 5000;
  const DatasetInfo abc = loadInput("builtin:abc", small).info();
  EXPECT_EQ(abc.format, "builtin");
  EXPECT_EQ(abc.time, 0.0);
  EXPECT_TRUE(abc.periodicKnown);
  EXPECT_EQ(abc.periodic, (std::array<bool, 3>{true, true, true}));
  for (const char* kind : {"builtin:rotation", "builtin:cloud"}) {
    const DatasetInfo info = loadInput(kind, small).info();
    EXPECT_TRUE(info.periodicKnown) << kind;
    EXPECT_EQ(info.periodic, (std::array<bool, 3>{false, false, false})) << kind;
  }
  // Generator levels count from the root blocks: level 0 is the coarsest of the 3.
  EXPECT_EQ(abc.fileLevel(2), 0);
  EXPECT_EQ(abc.fileLevel(0), 2);
}

}  // namespace
}  // namespace amrstream::formats
