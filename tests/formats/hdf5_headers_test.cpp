// The object headers read from the file's bytes against libhdf5, the oracle: every group's links
// (names and addresses) and every dataset's storage (shape, float size and byte order, offset,
// stored bytes) in files written with the oldest and the newest object header formats, the Enzo
// writer's files and the real Enzo and FLASH outputs; a dataset libhdf5 would not read in place, or
// a group whose links are stored otherwise, is declined, never misread; a damaged file is declined
// or read within its bounds, never a crash.

#include "formats/hdf5_headers.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "formats/dataset_writers.hpp"
#include "formats/hdf5_handle.hpp"
#include "synth/generators.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

namespace fs = std::filesystem;
using Links = std::vector<std::pair<std::string, std::uint64_t>>;

struct Counts {
  std::size_t groups = 0, groupsRead = 0, datasets = 0, datasetsRead = 0;
};

herr_t collectLink(hid_t, const char* name, const H5L_info_t* info, void* out) {
  if (info->type == H5L_TYPE_HARD) static_cast<Links*>(out)->emplace_back(name, info->u.address);
  return 0;
}

Links sorted(Links links) {
  std::ranges::sort(links);
  return links;
}

// What libhdf5 says of the dataset `set`: whether it is of the kind the header reader reads.
bool readsInPlace(hid_t set) {
  const Hdf5Handle type(H5Dget_type(set), H5Tclose);
  const Hdf5Handle plist(H5Dget_create_plist(set), H5Pclose);
  const Hdf5Handle space(H5Dget_space(set), H5Sclose);
  const bool ieee =
      H5Tequal(type.get(), H5T_IEEE_F32LE) > 0 || H5Tequal(type.get(), H5T_IEEE_F64LE) > 0 ||
      H5Tequal(type.get(), H5T_IEEE_F32BE) > 0 || H5Tequal(type.get(), H5T_IEEE_F64BE) > 0;
  const bool committed = H5Tcommitted(type.get()) > 0;
  return ieee && !committed && H5Pget_layout(plist.get()) == H5D_CONTIGUOUS &&
         H5Pget_nfilters(plist.get()) == 0 && H5Pget_external_count(plist.get()) == 0 &&
         H5Dget_offset(set) != HADDR_UNDEF && H5Sget_simple_extent_type(space.get()) != H5S_NULL;
}

// Every group and dataset under `group` (named `path`) compared with libhdf5.
void compareGroup(hid_t file, const Hdf5Headers& headers, const std::string& path,
                  std::uint64_t address, bool expectRead, Counts& counts) {
  Links links;
  ASSERT_GE(H5Literate_by_name(file, path.c_str(), H5_INDEX_NAME, H5_ITER_NATIVE, nullptr,
                               collectLink, &links, H5P_DEFAULT),
            0);
  ++counts.groups;
  const auto read = headers.groupLinks(address);
  if (expectRead) {
    EXPECT_TRUE(read) << "group " << path << " declined";
  }
  if (read) {
    ++counts.groupsRead;
    EXPECT_EQ(sorted(*read), sorted(links)) << "group " << path;
  }
  for (const auto& [name, at] : links) {
    const std::string child = (path == "/" ? "" : path) + "/" + name;
    H5O_info_t info;
    ASSERT_GE(H5Oget_info_by_name(file, child.c_str(), &info, H5P_DEFAULT), 0);
    if (info.type == H5O_TYPE_GROUP) {
      const Hdf5Handle g(H5Gopen2(file, child.c_str(), H5P_DEFAULT), H5Gclose);
      H5G_info_t groupInfo;
      ASSERT_GE(H5Gget_info(g.get(), &groupInfo), 0);
      // new-style groups of more than 8 links keep them in a fractal heap: declined
      const bool compact = groupInfo.storage_type != H5G_STORAGE_TYPE_DENSE;
      compareGroup(file, headers, child, at, compact, counts);
      continue;
    }
    if (info.type != H5O_TYPE_DATASET) continue;
    ++counts.datasets;
    const Hdf5Handle set(H5Dopen2(file, child.c_str(), H5P_DEFAULT), H5Dclose);
    const auto dataset = headers.contiguousDataset(at);
    if (!readsInPlace(set.get())) {
      EXPECT_FALSE(dataset) << child << " read, but libhdf5 would not read it in place";
      continue;
    }
    ASSERT_TRUE(dataset) << child << " declined";
    ++counts.datasetsRead;
    const Hdf5Handle space(H5Dget_space(set.get()), H5Sclose);
    std::vector<hsize_t> shape(H5Sget_simple_extent_ndims(space.get()));
    H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
    const Hdf5Handle type(H5Dget_type(set.get()), H5Tclose);
    EXPECT_EQ(dataset->shape, shape) << child;
    EXPECT_EQ(std::size_t(dataset->encoding.bytes), H5Tget_size(type.get())) << child;
    EXPECT_EQ(dataset->encoding.bigEndian, H5Tget_order(type.get()) == H5T_ORDER_BE) << child;
    EXPECT_EQ(dataset->offset, H5Dget_offset(set.get())) << child;
    EXPECT_EQ(dataset->storedBytes, H5Dget_storage_size(set.get())) << child;
  }
}

Counts compareFile(const fs::path& path) {
  Counts counts;
  const Hdf5Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  EXPECT_TRUE(file.valid()) << path;
  if (!file.valid()) return counts;
  const Hdf5Headers headers(path, file.get());
  EXPECT_TRUE(headers.usable());
  const auto root = rootLinks(file.get());
  EXPECT_TRUE(root);
  H5O_info_t info;
  EXPECT_GE(H5Oget_info(file.get(), &info), 0);
  H5G_info_t rootInfo;
  EXPECT_GE(H5Gget_info(file.get(), &rootInfo), 0);
  compareGroup(file.get(), headers, "/", info.addr, rootInfo.storage_type != H5G_STORAGE_TYPE_DENSE,
               counts);
  if (const auto read = headers.groupLinks(info.addr); root && read) {
    EXPECT_EQ(sorted(*root), sorted(*read));
  }
  return counts;
}

// A file of every kind of dataset and group, object headers of version 1 (`latest` false) or 2.
void writeVariety(const fs::path& path, bool latest) {
  const Hdf5Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (latest) H5Pset_libver_bounds(access.get(), H5F_LIBVER_LATEST, H5F_LIBVER_LATEST);
  const Hdf5Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()),
                        H5Fclose);
  ASSERT_TRUE(file.valid());
  const hsize_t dims[3] = {3, 4, 5};
  std::vector<double> values(60);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.5 * double(i);
  auto write = [&](hid_t where, const char* name, hid_t fileType, hid_t plist, int rank,
                   bool written = true) {
    const Hdf5Handle space(rank < 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(rank, dims, nullptr),
                           H5Sclose);
    const Hdf5Handle set(
        H5Dcreate2(where, name, fileType, space.get(), H5P_DEFAULT, plist, H5P_DEFAULT), H5Dclose);
    ASSERT_TRUE(set.valid()) << name;
    if (written) {
      ASSERT_GE(
          H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
    }
  };
  const hid_t root = file.get();
  write(root, "f32", H5T_IEEE_F32LE, H5P_DEFAULT, 3);
  write(root, "f64", H5T_IEEE_F64LE, H5P_DEFAULT, 2);
  write(root, "scalar", H5T_IEEE_F32LE, H5P_DEFAULT, -1);
  write(root, "line", H5T_IEEE_F64LE, H5P_DEFAULT, 1);
  write(root, "big_endian", H5T_IEEE_F32BE, H5P_DEFAULT, 3);
  write(root, "big_endian64", H5T_IEEE_F64BE, H5P_DEFAULT, 2);
  write(root, "integers", H5T_STD_I32LE, H5P_DEFAULT, 3);
  const Hdf5Handle chunked(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  const hsize_t chunk[3] = {1, 4, 5};
  H5Pset_chunk(chunked.get(), 3, chunk);
  H5Pset_deflate(chunked.get(), 4);
  write(root, "deflated", H5T_IEEE_F32LE, chunked.get(), 3);
  const Hdf5Handle compact(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_layout(compact.get(), H5D_COMPACT);
  write(root, "compact", H5T_IEEE_F32LE, compact.get(), 3);
  const Hdf5Handle late(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_alloc_time(late.get(), H5D_ALLOC_TIME_LATE);
  write(root, "never_written", H5T_IEEE_F32LE, late.get(), 3, false);
  const Hdf5Handle committed(H5Tcopy(H5T_IEEE_F32LE), H5Tclose);
  H5Tcommit2(root, "shared_type", committed.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  write(root, "of_shared_type", committed.get(), H5P_DEFAULT, 3);
  // a few links and many (dense storage in the newest format), nested, attributes on one
  const Hdf5Handle few(H5Gcreate2(root, "few", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  for (const char* name : {"a", "b", "c"}) write(few.get(), name, H5T_IEEE_F32LE, H5P_DEFAULT, 3);
  const Hdf5Handle nested(H5Gcreate2(few.get(), "nested", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                          H5Gclose);
  write(nested.get(), "deep", H5T_IEEE_F64LE, H5P_DEFAULT, 3);
  const Hdf5Handle many(H5Gcreate2(root, "many", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  for (int i = 0; i < 40; ++i)
    write(many.get(), ("set" + std::to_string(i)).c_str(), H5T_IEEE_F32LE, H5P_DEFAULT, 3);
  const Hdf5Handle attrSpace(H5Screate(H5S_SCALAR), H5Sclose);
  const Hdf5Handle attr(
      H5Acreate2(few.get(), "note", H5T_NATIVE_INT, attrSpace.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose);
  const int one = 1;
  H5Awrite(attr.get(), H5T_NATIVE_INT, &one);
}

class Hdf5HeadersTest : public testing::TempDirTest {};

TEST_F(Hdf5HeadersTest, VersionOneHeadersEqualLibhdf5) {
  writeVariety(dir_ / "v1.h5", false);
  const Counts counts = compareFile(dir_ / "v1.h5");
  EXPECT_EQ(counts.groups, 4u);
  EXPECT_EQ(counts.groupsRead, 4u);
  EXPECT_EQ(counts.datasets, 55u);
  // f32 f64 scalar line big_endian big_endian64, few's 4, many's 40
  EXPECT_EQ(counts.datasetsRead, 6u + 4 + 40);
}

TEST_F(Hdf5HeadersTest, VersionTwoHeadersEqualLibhdf5AndDenseGroupsAreDeclined) {
  writeVariety(dir_ / "v2.h5", true);
  const Counts counts = compareFile(dir_ / "v2.h5");
  EXPECT_EQ(counts.groups, 4u);
  EXPECT_EQ(counts.groupsRead, 2u);  // the root (13 links) and `many` are dense
  EXPECT_EQ(counts.datasetsRead, 50u);
}

TEST_F(Hdf5HeadersTest, TheEnzoWritersFilesEqualLibhdf5) {
  BuiltinOptions options;
  options.levels = 3;
  options.rootBlocks = 2;
  options.targetCells = 40000;
  writeFieldAs(synth::generate("cloud", options), dir_ / "cloud", "enzo");
  const Counts counts = compareFile(dir_ / "cloud.cpu0000");
  EXPECT_GE(counts.groups, 5u);
  EXPECT_EQ(counts.groupsRead, counts.groups);
  EXPECT_EQ(counts.datasetsRead, counts.datasets);
  EXPECT_GE(counts.datasets, 16u);
}

TEST_F(Hdf5HeadersTest, RealEnzoAndFlashOutputsEqualLibhdf5) {
  const fs::path real = AMRSTREAM_REAL_DATA_DIR;
  const fs::path enzo = real / "enzo-moving7/DD0010/moving7_0010.cpu0000";
  const fs::path flash = real / "flash-2d-nanowire/nanowire_arrayhdf5_plt_cnt_0100";
  if (!fs::exists(enzo) || !fs::exists(flash))
    GTEST_SKIP() << "the real outputs are not in " << real;
  const Counts e = compareFile(enzo);  // Enzo wrote big-endian float32
  EXPECT_GT(e.datasetsRead, 10u);
  EXPECT_EQ(e.groupsRead, e.groups);
  const Counts f = compareFile(flash);
  EXPECT_GT(f.datasets, 0u);
}

// Every header of the pristine file read again in copies with bytes changed or cut short: an
// answer is nullopt or lies within the damaged file.
TEST_F(Hdf5HeadersTest, DamagedFilesAreDeclinedOrReadWithinTheirBounds) {
  writeVariety(dir_ / "v1.h5", false);
  writeVariety(dir_ / "v2.h5", true);
  std::mt19937 random(7);
  for (const char* name : {"v1.h5", "v2.h5"}) {
    std::vector<std::uint64_t> addresses;
    {
      const Hdf5Handle file(H5Fopen((dir_ / name).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
      const Hdf5Headers headers(dir_ / name, file.get());
      H5O_info_t info;
      ASSERT_GE(H5Oget_info(file.get(), &info), 0);
      addresses.push_back(info.addr);
      const auto root = rootLinks(file.get());
      ASSERT_TRUE(root);
      for (const auto& [n, at] : *root) {
        addresses.push_back(at);
        if (const auto links = headers.groupLinks(at))
          for (const auto& link : *links) addresses.push_back(link.second);
      }
    }
    std::ifstream in(dir_ / name, std::ios::binary);
    const std::string pristine((std::istreambuf_iterator<char>(in)), {});
    for (int copy = 0; copy < 300; ++copy) {
      std::string bytes = pristine;
      if (copy % 3 == 0) {
        bytes.resize(random() % bytes.size());
      } else {
        for (int flip = 0; flip < 8; ++flip)
          bytes[random() % bytes.size()] ^= char(1 + random() % 255);
      }
      const fs::path damaged = dir_ / "damaged.h5";
      std::ofstream(damaged, std::ios::binary | std::ios::trunc) << bytes;
      // the sizes come from the pristine file: a damaged superblock would not open
      const Hdf5Handle file(H5Fopen((dir_ / name).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
      const Hdf5Headers headers(damaged, file.get());
      for (std::uint64_t at : addresses) {
        (void)headers.groupLinks(at);
        if (const auto dataset = headers.contiguousDataset(at)) {
          EXPECT_LT(at, bytes.size());
          EXPECT_FALSE(dataset->shape.size() > H5S_MAX_RANK);
        }
      }
    }
  }
}

}  // namespace
}  // namespace amrstream::formats
