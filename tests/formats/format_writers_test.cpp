// The FLASH, Enzo and AMReX writers (amrstream gen --format): a generated cloud written in each
// format reads back, through our readers, as exactly the cells and values of its ExaBricks files;
// values read through file offsets equal those HDF5 reads from chunked, compressed copies; a
// value window reads part of the values; truncated files give errors naming the file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/amrex/amrex_reader.hpp"
#include "formats/dataset_writers.hpp"
#include "formats/enzo/enzo_reader.hpp"
#include "formats/exa/exa_format.hpp"
#include "formats/flash/flash_reader.hpp"
#include "input_error_of.hpp"
#include "synth/generators.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::inputErrorOf;

bricks::AmrField smallCloud() {
  BuiltinOptions options;
  options.levels = 3;
  options.rootBlocks = 2;
  options.targetCells = 40000;
  return synth::generate("cloud", options);
}

// The cells as (corner, level, values...) in corner order, for comparing fields whatever their
// cell order.
using CellRow = std::tuple<int, int, int, int, std::vector<float>>;
std::vector<CellRow> rows(const bricks::AmrField& field) {
  std::vector<CellRow> result;
  for (std::size_t i = 0; i < field.cellCount(); ++i) {
    std::vector<float> values;
    for (const Channel& channel : field.channels()) values.push_back(channel.values[i]);
    const glm::ivec3 c = field.lowers()[i];
    result.emplace_back(c.z, c.y, c.x, field.levels()[i], std::move(values));
  }
  std::sort(result.begin(), result.end());
  return result;
}

std::vector<std::string> names(const bricks::AmrField& field) {
  std::vector<std::string> result;
  for (const Channel& channel : field.channels()) result.push_back(channel.name);
  return result;
}

bricks::AmrField readAs(const fs::path& path, const std::string& format,
                        const ValueWindow* window = nullptr, WindowedRead* read = nullptr) {
  if (format == "flash") return readFlash(path, window, read);
  if (format == "enzo") return readEnzo(path, window, read);
  if (format == "amrex") return readAmrexPlotfile(path, window, read);
  return readExa(path);
}

class FormatWritersTest : public testing::TempDirTest,
                          public ::testing::WithParamInterface<std::string> {};

TEST_P(FormatWritersTest, ReadsBackTheCellsAndValuesOfTheExaRoute) {
  const bricks::AmrField cloud = smallCloud();
  const auto exa = readExa(writeFieldAs(cloud, dir_ / "cloud", "exa"));
  const fs::path written = writeFieldAs(cloud, dir_ / "cloud", GetParam());
  EXPECT_EQ(written, writtenPath(dir_ / "cloud", GetParam()));
  const auto field = readAs(written, GetParam());
  EXPECT_EQ(names(field), names(exa));
  EXPECT_EQ(field.cellCount(), exa.cellCount());
  EXPECT_TRUE(rows(field) == rows(exa)) << GetParam() << " cells or values differ";
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(field.transform().origin[a], exa.transform().origin[a], 1e-12);
    EXPECT_NEAR(field.transform().spacing[a], exa.transform().spacing[a], 1e-12);
  }
}

TEST_P(FormatWritersTest, AWindowReadsTheValuesNearItAndTheCellsOfAll) {
  const bricks::AmrField cloud = smallCloud();
  const fs::path written = writeFieldAs(cloud, dir_ / "cloud", GetParam());
  const auto whole = readAs(written, GetParam());
  ValueWindow window;
  const glm::ivec3 upper = whole.bounds().upper;
  window.boxes.push_back({glm::ivec3(0), upper / 4});
  WindowedRead read;
  const auto part = readAs(written, GetParam(), &window, &read);
  ASSERT_EQ(part.cellCount(), whole.cellCount());
  EXPECT_GT(read.piecesRead, 0u);
  EXPECT_LT(read.piecesRead, read.pieces);
  std::size_t inside = 0;
  for (std::size_t i = 0; i < whole.cellCount(); ++i) {
    if (glm::any(glm::greaterThanEqual(whole.lowers()[i], upper / 4))) continue;
    ++inside;
    for (std::size_t c = 0; c < whole.channels().size(); ++c)
      ASSERT_EQ(part.channels()[c].values[i], whole.channels()[c].values[i]) << "cell " << i;
  }
  EXPECT_GT(inside, 0u);
}

TEST_P(FormatWritersTest, AFailedWriteLeavesNothing) {
  const bricks::AmrField cloud = smallCloud();
  const fs::path missing = dir_ / "no-such-folder" / "cloud";
  EXPECT_THROW(writeFieldAs(cloud, missing, GetParam()), InputError);
  EXPECT_TRUE(fs::is_empty(dir_));
}

INSTANTIATE_TEST_SUITE_P(Formats, FormatWritersTest, ::testing::Values("flash", "enzo", "amrex"));

// ---- the H5Dread fallback ------------------------------------------------------------------

// Rewrites dataset `name` of `file` chunked and deflated: HDF5 must then read it.
void compress(const fs::path& file, const std::string& name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const hid_t set = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(rank);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  std::vector<float> values(
      std::accumulate(dims.begin(), dims.end(), hsize_t(1), std::multiplies<>()));
  ASSERT_GE(H5Dread(set, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Dclose(set);
  ASSERT_GE(H5Ldelete(f, name.c_str(), H5P_DEFAULT), 0);
  const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
  std::vector<hsize_t> chunk = dims;
  chunk[0] = 1;
  H5Pset_chunk(plist, rank, chunk.data());
  H5Pset_deflate(plist, 6);
  const hid_t packed =
      H5Dcreate2(f, name.c_str(), H5T_IEEE_F32BE, space, H5P_DEFAULT, plist, H5P_DEFAULT);
  ASSERT_GE(H5Dwrite(packed, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Dclose(packed);
  H5Pclose(plist);
  H5Sclose(space);
  H5Fclose(f);
}

using FallbackTest = testing::TempDirTest;

TEST_F(FallbackTest, FlashValuesReadThroughOffsetsEqualHdf5s) {
  const bricks::AmrField cloud = smallCloud();
  const fs::path contiguous = writeFieldAs(cloud, dir_ / "plain", "flash");
  const fs::path packed = writeFieldAs(cloud, dir_ / "packed", "flash");
  compress(packed, "dens");
  compress(packed, "magy");
  EXPECT_TRUE(rows(readFlash(packed)) == rows(readFlash(contiguous)));
  ValueWindow window;
  window.boxes.push_back({glm::ivec3(0), cloud.bounds().upper / 3});
  const auto a = readFlash(packed, &window), b = readFlash(contiguous, &window);
  EXPECT_TRUE(rows(a) == rows(b));
}

TEST_F(FallbackTest, EnzoValuesReadThroughOffsetsEqualHdf5s) {
  const bricks::AmrField cloud = smallCloud();
  const fs::path contiguous = writeFieldAs(cloud, dir_ / "plain", "enzo");
  const fs::path packed = writeFieldAs(cloud, dir_ / "packed", "enzo");
  for (const char* grid : {"Grid00000001", "Grid00000003"})
    for (const Channel& channel : cloud.channels())
      compress(dir_ / "packed.cpu0000", std::string(grid) + "/" + channel.name);
  EXPECT_TRUE(rows(readEnzo(packed)) == rows(readEnzo(contiguous)));
}

// ---- truncated files -----------------------------------------------------------------------

using TruncatedTest = testing::TempDirTest;

TEST_F(TruncatedTest, AShortFlashFileNamesTheFile) {
  const fs::path file = writeFieldAs(smallCloud(), dir_ / "cloud", "flash");
  fs::resize_file(file, fs::file_size(file) / 2);
  EXPECT_THAT(inputErrorOf([&] { readFlash(file); }), HasSubstr(file.string()));
}

TEST_F(TruncatedTest, AShortEnzoFieldFileNamesTheFile) {
  const fs::path prefix = writeFieldAs(smallCloud(), dir_ / "cloud", "enzo");
  const fs::path cpu = dir_ / "cloud.cpu0000";
  fs::resize_file(cpu, fs::file_size(cpu) * 3 / 4);
  EXPECT_THAT(inputErrorOf([&] { readEnzo(prefix); }), HasSubstr(cpu.string()));
}

TEST_F(TruncatedTest, AShortAmrexFabFileNamesTheFile) {
  const fs::path plotfile = writeFieldAs(smallCloud(), dir_ / "cloud", "amrex");
  const fs::path data = plotfile / "Level_0" / "Cell_D_00000";
  fs::resize_file(data, fs::file_size(data) - 100);
  EXPECT_THAT(inputErrorOf([&] { readAmrexPlotfile(plotfile); }), HasSubstr(data.string()));
}

}  // namespace
}  // namespace amrstream::formats
