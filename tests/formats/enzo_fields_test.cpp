// The Enzo grids' field values read in batches while more grids are added: with batches of
// every size, the values equal those H5Dread gives, and of several unusable values the one
// reported is the first in the order the datasets were added, whichever batch met it first;
// the same with the datasets found from their object headers, which leave to libhdf5 the groups
// and fields they do not find.

#include "formats/enzo/enzo_fields.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/dataset_writers.hpp"
#include "formats/enzo/enzo_grid_headers.hpp"
#include "input_error_of.hpp"
#include "synth/generators.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats::enzo {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using testing::inputErrorOf;

const std::vector<std::string> kChannels = {"dens", "magx", "magy", "magz"};

struct GridValues {
  std::string group;
  glm::ivec3 dims;
  std::vector<std::vector<float>> channels;  // what H5Dread gives
};

// The grids of `file` (a field file the Enzo writer wrote) with their values as H5Dread reads them.
std::vector<GridValues> readWithHdf5(const fs::path& file) {
  std::vector<GridValues> grids;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0);
  for (int id = 1;; ++id) {
    const std::string group = fmt::format("/Grid{:08d}", id);
    if (H5Lexists(f, group.c_str(), H5P_DEFAULT) <= 0) break;
    GridValues grid{group, glm::ivec3(0), {}};
    for (const std::string& name : kChannels) {
      const hid_t set = H5Dopen2(f, (group + "/" + name).c_str(), H5P_DEFAULT);
      const hid_t space = H5Dget_space(set);
      hsize_t dims[3] = {0, 0, 0};
      H5Sget_simple_extent_dims(space, dims, nullptr);
      grid.dims = glm::ivec3(int(dims[2]), int(dims[1]), int(dims[0]));
      std::vector<float> values(dims[0] * dims[1] * dims[2]);
      EXPECT_GE(H5Dread(set, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
      grid.channels.push_back(std::move(values));
      H5Sclose(space);
      H5Dclose(set);
    }
    grids.push_back(std::move(grid));
  }
  H5Fclose(f);
  return grids;
}

// The grids' datasets found from their object headers.
std::vector<GridDatasets> fromHeaders(hid_t f, const fs::path& file,
                                      const std::vector<GridValues>& grids) {
  const FieldFile files[] = {{file, f}};
  std::vector<GridGroup> groups;
  for (const GridValues& grid : grids) groups.push_back({0, grid.group, true});
  return findGridDatasets(files, groups, kChannels);
}

// Every grid of `file` added to a FieldReads of `batchValues` and read into `into` (sized as
// `grids`' values); `headers`: the datasets found from their object headers, not opened.
void readWithBatches(const fs::path& file, const std::vector<GridValues>& grids,
                     std::vector<std::vector<std::vector<float>>>& into, std::uint64_t batchValues,
                     bool headers = false) {
  into.clear();
  for (const GridValues& grid : grids) {
    std::vector<std::vector<float>> channels;
    for (const auto& values : grid.channels) channels.emplace_back(values.size(), -1.0f);
    into.push_back(std::move(channels));
  }
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  {
    const std::vector<GridDatasets> found =
        headers ? fromHeaders(f, file, grids) : std::vector<GridDatasets>(grids.size());
    FieldReads reads(kChannels, batchValues);
    for (std::size_t g = 0; g < grids.size(); ++g) {
      std::vector<float*> targets;
      for (auto& values : into[g]) targets.push_back(values.data());
      if (headers) {
        ASSERT_EQ(found[g].channels.size(), kChannels.size()) << grids[g].group;
        reads.addInPlace(file, grids[g].group, grids[g].dims, 3, targets, found[g].channels,
                         found[g].fileBytes);
        continue;
      }
      const hid_t group = H5Gopen2(f, grids[g].group.c_str(), H5P_DEFAULT);
      reads.add(group, file, grids[g].group, grids[g].dims, 3, targets);
      H5Gclose(group);
    }
    reads.run();
  }
  H5Fclose(f);
}

// Overwrites value `index` of `group`/`name` in place (the dataset keeps its contiguous storage).
void spoil(const fs::path& file, const std::string& group, const std::string& name,
           std::size_t index, float value) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  const hid_t set = H5Dopen2(f, (group + "/" + name).c_str(), H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  std::vector<float> values(std::size_t(H5Sget_simple_extent_npoints(space)));
  ASSERT_GE(H5Dread(set, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  values.at(index) = value;
  ASSERT_GE(H5Dwrite(set, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(f);
}

// The grids' values written again to `file` as big-endian float32 (even channels) and float64
// (odd ones), contiguous, as Enzo itself writes them.
void writeBigEndian(const fs::path& file, const std::vector<GridValues>& grids) {
  const hid_t f = H5Fcreate(file.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  for (const GridValues& grid : grids) {
    const hid_t group = H5Gcreate2(f, grid.group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const hsize_t dims[3] = {hsize_t(grid.dims.z), hsize_t(grid.dims.y), hsize_t(grid.dims.x)};
    const hid_t space = H5Screate_simple(3, dims, nullptr);
    for (std::size_t c = 0; c < kChannels.size(); ++c) {
      const hid_t set =
          H5Dcreate2(group, kChannels[c].c_str(), c % 2 ? H5T_IEEE_F64BE : H5T_IEEE_F32BE, space,
                     H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      EXPECT_GE(
          H5Dwrite(set, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, grid.channels[c].data()),
          0);
      H5Dclose(set);
    }
    H5Sclose(space);
    H5Gclose(group);
  }
  H5Fclose(f);
}

class FieldReadsTest : public testing::TempDirTest {
 protected:
  void SetUp() override {
    testing::TempDirTest::SetUp();
    BuiltinOptions options;
    options.levels = 3;
    options.rootBlocks = 2;
    options.targetCells = 40000;
    writeFieldAs(synth::generate("cloud", options), dir_ / "cloud", "enzo");
    file_ = dir_ / "cloud.cpu0000";
    grids_ = readWithHdf5(file_);
    ASSERT_GE(grids_.size(), 4u);
  }
  fs::path file_;
  std::vector<GridValues> grids_;
};

TEST_F(FieldReadsTest, EveryBatchSizeReadsTheValuesHdf5Reads) {
  for (const bool headers : {false, true})
    for (const std::uint64_t batch :
         {std::uint64_t(1), std::uint64_t(1000), std::uint64_t(1) << 40}) {
      std::vector<std::vector<std::vector<float>>> into;
      readWithBatches(file_, grids_, into, batch, headers);
      for (std::size_t g = 0; g < grids_.size(); ++g)
        for (std::size_t c = 0; c < kChannels.size(); ++c)
          ASSERT_EQ(into[g][c], grids_[g].channels[c])
              << "batch " << batch << ", " << grids_[g].group << "/" << kChannels[c]
              << (headers ? ", from the headers" : "");
    }
}

TEST_F(FieldReadsTest, BigEndianValuesAreReadInPlaceAsHdf5ReadsThem) {
  const fs::path swapped = dir_ / "big_endian.cpu0000";
  writeBigEndian(swapped, grids_);
  const auto values = readWithHdf5(swapped);
  ASSERT_EQ(values.size(), grids_.size());
  for (const bool headers : {false, true}) {
    std::vector<std::vector<std::vector<float>>> into;
    readWithBatches(swapped, values, into, 1000, headers);
    for (std::size_t g = 0; g < values.size(); ++g)
      for (std::size_t c = 0; c < kChannels.size(); ++c)
        ASSERT_EQ(into[g][c], values[g].channels[c])
            << values[g].group << "/" << kChannels[c] << (headers ? ", from the headers" : "");
  }
  spoil(swapped, grids_[2].group, "magx", 7, std::numeric_limits<float>::quiet_NaN());
  const std::string error = fmt::format("dataset {}/magx: value nan at zone", grids_[2].group);
  for (const bool headers : {false, true}) {
    std::vector<std::vector<std::vector<float>>> into;
    EXPECT_THAT(inputErrorOf([&] { readWithBatches(swapped, values, into, 1000, headers); }),
                HasSubstr(error));
  }
}

TEST_F(FieldReadsTest, GroupsNotInTheFileOrAFileLibhdf5CouldNotOpenAreLeftToIt) {
  const hid_t f = H5Fopen(file_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  const FieldFile files[] = {{file_, f}, {file_, H5I_INVALID_HID}};
  const std::vector<GridGroup> groups = {{0, grids_[0].group, true},
                                         {0, "/Grid99999999", true},
                                         {1, grids_[0].group, true},
                                         {0, grids_[1].group, false}};
  const auto found = findGridDatasets(files, groups, kChannels);
  H5Fclose(f);
  ASSERT_EQ(found.size(), 4u);
  EXPECT_TRUE(found[0].groupFound);
  EXPECT_EQ(found[0].channels.size(), kChannels.size());
  EXPECT_EQ(found[0].fileBytes, fs::file_size(file_));
  EXPECT_FALSE(found[1].groupFound);
  EXPECT_FALSE(found[2].groupFound);
  EXPECT_TRUE(found[2].channels.empty());
  EXPECT_TRUE(found[3].groupFound);  // its values are not wanted: no datasets looked for
  EXPECT_TRUE(found[3].channels.empty());
  const std::vector<std::string> absent = {"dens", "no_such_field"};
  const GridGroup one[] = {{0, grids_[0].group, true}};
  const hid_t again = H5Fopen(file_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const FieldFile file[] = {{file_, again}};
  const auto partial = findGridDatasets(file, one, absent);
  H5Fclose(again);
  EXPECT_TRUE(partial[0].groupFound);
  EXPECT_TRUE(partial[0].channels.empty());  // one channel missing: libhdf5 names it
}

TEST_F(FieldReadsTest, TheFirstUnusableValueInTheOrderAddedIsNamedWhateverTheBatches) {
  // A NaN in the last grid, infinities in grid 2's magx and, earlier in the order added, its dens.
  spoil(file_, grids_.back().group, "dens", 0, std::numeric_limits<float>::quiet_NaN());
  spoil(file_, grids_[1].group, "magx", 3, std::numeric_limits<float>::infinity());
  spoil(file_, grids_[1].group, "dens", 5, -std::numeric_limits<float>::infinity());
  const std::string expected =
      fmt::format("dataset {}/dens: value -inf at zone (i, j, k) = (5, 0, 0)", grids_[1].group);
  for (const std::uint64_t batch :
       {std::uint64_t(1), std::uint64_t(1000), std::uint64_t(1) << 40}) {
    for (const bool headers : {false, true}) {
      std::vector<std::vector<std::vector<float>>> into;
      const std::string error =
          inputErrorOf([&] { readWithBatches(file_, grids_, into, batch, headers); });
      EXPECT_THAT(error, HasSubstr(file_.string())) << "batch " << batch;
      EXPECT_THAT(error, HasSubstr(expected)) << "batch " << batch;
    }
  }
}

}  // namespace
}  // namespace amrstream::formats::enzo
