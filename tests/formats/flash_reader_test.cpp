// FLASH (PARAMESH) HDF5 files: the real 2D nanowire plotfile and small multi-level files written
// here with the HDF5 C API read back as their leaf cells with the right values and transform;
// missing, misshapen, inconsistent and truncated files are rejected with errors naming the file.

#include "formats/flash/flash_reader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "hdf5_read.hpp"
#include "input_error_of.hpp"
#include "special_files.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
namespace fs = std::filesystem;
using testing::inputErrorOf;

const fs::path kRealFile =
    fs::path(AMRSTREAM_REAL_DATA_DIR) / "flash-2d-nanowire" / "nanowire_arrayhdf5_plt_cnt_0100";

// ---- writing FLASH-layout files -------------------------------------------------------------

struct Block {
  int refine;
  int nodeType;
  glm::dvec3 lo, hi;
};

// A root block split into 2^dim children; the first child split again (node types 2 / 1).
std::vector<Block> makeTree(int dim, glm::dvec3 lo, glm::dvec3 hi) {
  std::vector<Block> blocks{{1, 2, lo, hi}};
  const auto split = [&](Block parent,  // a copy: push_back moves the tree
                         int refine, int firstType) {
    const glm::dvec3 half = (parent.hi - parent.lo) * 0.5;
    for (int c = 0; c < (1 << dim); ++c) {
      const glm::dvec3 off(c & 1, (c >> 1) & 1, (c >> 2) & 1);
      Block child{refine, c == 0 ? firstType : 1, parent.lo + off * half,
                  parent.lo + off * half + half};
      if (dim == 2) child.hi.z = child.lo.z = parent.lo.z;
      blocks.push_back(child);
    }
  };
  split(blocks[0], 2, 2);
  split(blocks[1], 3, 1);
  return blocks;
}

double velx(glm::dvec3 c) { return c.x + 2.0 * c.y; }
double vely(glm::dvec3 c) { return c.y * c.z; }
double velz(glm::dvec3 c) { return std::sin(c.x) + c.z; }
double dens(glm::dvec3 c) { return 1.0 + c.x * c.x; }
const std::vector<std::pair<std::string, std::function<double(glm::dvec3)>>> kFunctions{
    {"velx", velx}, {"vely", vely}, {"velz", velz}, {"dens", dens}};
constexpr double kParentValue = -999.0;

// How `unknown names` stores its strings: FLASH's Fortran writes them exactly 4 wide; h5py pads
// with NULs, others with blanks or a terminating NUL, or writes variable-length strings.
enum class NameStorage { kExactWidth, kNullPadded, kSpacePadded, kNullTerminated, kVariable };

struct Corruption {
  NameStorage nameStorage = NameStorage::kExactWidth;
  bool omitNodeType = false;
  bool wrongShapeDens = false;
  bool listAbsentVariable = false;
  bool badBlockSize = false;
  bool omitScalars = false;
};

void writeArray(hid_t file, const char* name, hid_t type, const std::vector<hsize_t>& dims,
                const void* data) {
  const hid_t space = H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr);
  const hid_t set = H5Dcreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(set, 0) << name;
  ASSERT_GE(H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), 0) << name;
  H5Dclose(set);
  H5Sclose(space);
}

void writeNames(hid_t file, const std::vector<std::string>& names, NameStorage storage) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  const hsize_t count = names.size();
  if (storage == NameStorage::kVariable) {
    H5Tset_size(type, H5T_VARIABLE);
    std::vector<const char*> pointers;
    for (const std::string& name : names) pointers.push_back(name.c_str());
    writeArray(file, "unknown names", type, {count, 1}, pointers.data());
    H5Tclose(type);
    return;
  }
  // h5py's numpy 'S4' names are null-padded exactly 4 wide: a NUL-terminated memory type of
  // width 4 would keep 3 characters of each.
  const std::size_t width = storage == NameStorage::kNullTerminated ? 5
                            : storage == NameStorage::kSpacePadded  ? 8
                                                                    : 4;
  H5Tset_size(type, width);
  H5Tset_strpad(type, storage == NameStorage::kNullPadded    ? H5T_STR_NULLPAD
                      : storage == NameStorage::kSpacePadded ? H5T_STR_SPACEPAD
                                                             : H5T_STR_NULLTERM);
  std::string bytes;
  for (const std::string& name : names) {
    std::string padded = name;
    padded.resize(width, storage == NameStorage::kSpacePadded ? ' ' : '\0');
    bytes += padded;
  }
  writeArray(file, "unknown names", type, {count, 1}, bytes.data());
  H5Tclose(type);
}

struct IntScalar {
  char name[80];
  int value;
};

void writeFlash(const fs::path& path, int dim, const std::vector<Block>& blocks,
                const Corruption& bad = {}) {
  const int nxb = 4, nyb = 4, nzb = dim == 3 ? 4 : 1;
  const hid_t file = H5Fcreate(path.string().c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hsize_t nb = blocks.size();

  std::vector<std::string> names;
  for (const auto& [name, f] : kFunctions) names.push_back(name);
  if (bad.listAbsentVariable) names.push_back("pres");
  writeNames(file, names, bad.nameStorage);

  if (!bad.omitScalars) {
    const hid_t nameType = H5Tcopy(H5T_C_S1);
    H5Tset_size(nameType, 80);
    const hid_t type = H5Tcreate(H5T_COMPOUND, sizeof(IntScalar));
    H5Tinsert(type, "name", HOFFSET(IntScalar, name), nameType);
    H5Tinsert(type, "value", HOFFSET(IntScalar, value), H5T_NATIVE_INT);
    std::vector<IntScalar> scalars(4);
    const std::pair<const char*, int> entries[] = {
        {"nxb", nxb}, {"nyb", nyb}, {"nzb", nzb}, {"dimensionality", dim}};
    for (int i = 0; i < 4; ++i) {
      std::memset(scalars[i].name, ' ', 80);
      std::memcpy(scalars[i].name, entries[i].first, std::strlen(entries[i].first));
      scalars[i].value = entries[i].second;
    }
    writeArray(file, "integer scalars", type, {4}, scalars.data());
    H5Tclose(type);
    H5Tclose(nameType);
  }

  std::vector<int> refine, nodeType;
  std::vector<double> bbox, size, centre;
  for (const Block& b : blocks) {
    refine.push_back(b.refine);
    nodeType.push_back(b.nodeType);
    for (int a = 0; a < 3; ++a) {
      bbox.insert(bbox.end(), {b.lo[a], b.hi[a]});
      size.push_back(b.hi[a] - b.lo[a]);
      centre.push_back(0.5 * (b.lo[a] + b.hi[a]));
    }
  }
  if (bad.badBlockSize) size[3 * 4 + 1] *= 2.0;
  writeArray(file, "refine level", H5T_NATIVE_INT, {nb}, refine.data());
  if (!bad.omitNodeType) writeArray(file, "node type", H5T_NATIVE_INT, {nb}, nodeType.data());
  writeArray(file, "bounding box", H5T_NATIVE_DOUBLE, {nb, 3, 2}, bbox.data());
  writeArray(file, "block size", H5T_NATIVE_DOUBLE, {nb, 3}, size.data());
  writeArray(file, "coordinates", H5T_NATIVE_DOUBLE, {nb, 3}, centre.data());

  for (const auto& [name, f] : kFunctions) {
    std::vector<double> values;
    for (const Block& b : blocks) {
      const glm::dvec3 d = (b.hi - b.lo) / glm::dvec3(nxb, nyb, nzb);
      for (int k = 0; k < nzb; ++k)
        for (int j = 0; j < nyb; ++j)
          for (int i = 0; i < nxb; ++i)
            values.push_back(b.nodeType == 1 ? f(b.lo + (glm::dvec3(i, j, k) + 0.5) * d)
                                             : kParentValue);
    }
    std::vector<hsize_t> dims{nb, hsize_t(nzb), hsize_t(nyb), hsize_t(nxb)};
    if (name == "dens") {
      if (bad.wrongShapeDens) dims = {nb, hsize_t(nzb), hsize_t(nyb * nxb)};
      const std::vector<float> floats(values.begin(), values.end());
      writeArray(file, name.c_str(), H5T_NATIVE_FLOAT, dims, floats.data());
    } else {
      writeArray(file, name.c_str(), H5T_NATIVE_DOUBLE, dims, values.data());
    }
  }
  H5Fclose(file);
}

// Adds `real scalars` and `string runtime parameters` name/value lists to a written file.
void addMetadata(const fs::path& path, const std::vector<std::pair<std::string, double>>& reals,
                 const std::vector<std::pair<std::string, std::string>>& strings) {
  struct RealPair {
    char name[80];
    double value;
  };
  struct StringPair {
    char name[80];
    char value[80];
  };
  const auto blankPadded = [](char* to, const std::string& from) {
    std::memset(to, ' ', 80);
    std::memcpy(to, from.data(), from.size());
  };
  const hid_t file = H5Fopen(path.string().c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t text = H5Tcopy(H5T_C_S1);
  H5Tset_size(text, 80);
  const hid_t realType = H5Tcreate(H5T_COMPOUND, sizeof(RealPair));
  H5Tinsert(realType, "name", HOFFSET(RealPair, name), text);
  H5Tinsert(realType, "value", HOFFSET(RealPair, value), H5T_NATIVE_DOUBLE);
  std::vector<RealPair> realPairs(reals.size());
  for (std::size_t i = 0; i < reals.size(); ++i) {
    blankPadded(realPairs[i].name, reals[i].first);
    realPairs[i].value = reals[i].second;
  }
  if (!reals.empty()) writeArray(file, "real scalars", realType, {reals.size()}, realPairs.data());
  const hid_t stringType = H5Tcreate(H5T_COMPOUND, sizeof(StringPair));
  H5Tinsert(stringType, "name", HOFFSET(StringPair, name), text);
  H5Tinsert(stringType, "value", HOFFSET(StringPair, value), text);
  std::vector<StringPair> stringPairs(strings.size());
  for (std::size_t i = 0; i < strings.size(); ++i) {
    blankPadded(stringPairs[i].name, strings[i].first);
    blankPadded(stringPairs[i].value, strings[i].second);
  }
  if (!strings.empty())
    writeArray(file, "string runtime parameters", stringType, {strings.size()}, stringPairs.data());
  H5Tclose(stringType);
  H5Tclose(realType);
  H5Tclose(text);
  H5Fclose(file);
}

class FlashReader : public testing::TempDirTest {
 protected:
};

const glm::dvec3 kLo(-1.0, 0.0, 2.0), kHi(1.0, 1.0, 2.5);

glm::dvec3 cellCentre(const bricks::AmrField& field, std::size_t c) {
  const double w = bricks::AmrField::cellWidth(field.levels()[c]);
  return field.transform().toPhysical(glm::dvec3(field.lowers()[c]) + 0.5 * w);
}

void expectNear(glm::dvec3 actual, glm::dvec3 expected, double tolerance) {
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(actual[a], expected[a], tolerance) << "axis " << a;
}

// ---- synthetic files ------------------------------------------------------------------------

TEST_F(FlashReader, ThreeDimensionalTreeKeepsLeavesWithAnalyticValues) {
  const fs::path path = dir_ / "tree_hdf5_chk_0000";
  writeFlash(path, 3, makeTree(3, kLo, kHi));
  const bricks::AmrField field = readFlash(path);

  EXPECT_EQ(field.cellCount(), 15u * 64u);  // 7 level-2 leaves + 8 level-3 leaves, parents dropped
  EXPECT_THAT(field.cellsPerLevel(), ElementsAre(8u * 64u, 7u * 64u));
  expectNear(field.transform().origin, kLo, 1e-12);
  expectNear(field.transform().spacing, (kHi - kLo) / 16.0, 1e-12);
  expectNear(field.transform().toPhysical(glm::dvec3(field.bounds().lower)), kLo, 1e-12);
  expectNear(field.transform().toPhysical(glm::dvec3(field.bounds().upper)), kHi, 1e-12);

  std::vector<std::string> names;
  for (const auto& channel : field.channels()) names.push_back(channel.name);
  EXPECT_THAT(names, ElementsAre("velx", "vely", "velz", "dens"));
  for (const auto& [name, f] : kFunctions) {
    const auto& values = field.channel(name).values;
    for (std::size_t c = 0; c < field.cellCount(); ++c) {
      const double expected = f(cellCentre(field, c));
      ASSERT_NEAR(values[c], expected, 1e-5 * (1.0 + std::abs(expected))) << name << " cell " << c;
    }
  }
}

TEST_F(FlashReader, BlockShapeComesFromTheVariablesWhenScalarsAreAbsent) {
  const fs::path path = dir_ / "noscalars";
  writeFlash(path, 3, makeTree(3, kLo, kHi), {.omitScalars = true});
  EXPECT_EQ(readFlash(path).cellCount(), 15u * 64u);
}

TEST_F(FlashReader, TwoDimensionalMixedLevelsFormAUniformSlab) {
  const fs::path path = dir_ / "flat_hdf5_plt_cnt_0000";
  writeFlash(path, 2, makeTree(2, kLo, kHi));
  const bricks::AmrField field = readFlash(path);

  // 3 coarse leaves (level 1) once, 4 fine leaves (level 0) stacked twice: slab 2 cells thick,
  // across z = 0, the 2D dataset's plane.
  EXPECT_EQ(field.cellCount(), 3u * 16u + 4u * 16u * 2u);
  EXPECT_EQ(field.bounds().lower.z, 0);
  EXPECT_EQ(field.bounds().upper.z, 2);
  EXPECT_EQ(field.transform().spacing.z, field.transform().spacing.x);
  expectNear(glm::dvec3(field.transform().toPhysical(glm::dvec3(field.bounds().upper))),
             glm::dvec3(kHi.x, kHi.y, field.transform().spacing.x), 1e-12);
  EXPECT_EQ(field.transform().toPhysical(glm::dvec3(field.bounds().lower)).z,
            -field.transform().spacing.x);
  EXPECT_EQ(field.info().dimensions, 2);
  const auto& values = field.channel("velx").values;
  for (std::size_t c = 0; c < field.cellCount(); ++c) {
    const glm::dvec3 centre = cellCentre(field, c);
    ASSERT_NEAR(values[c], velx(centre), 1e-5) << "cell " << c;
  }
}

TEST_F(FlashReader, MissingNodeTypeIsRejected) {
  const fs::path path = dir_ / "no_node_type";
  writeFlash(path, 3, makeTree(3, kLo, kHi), {.omitNodeType = true});
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              AllOf(HasSubstr(path.string()), HasSubstr("'node type'"), HasSubstr("missing")));
}

TEST_F(FlashReader, VariableWithWrongShapeIsRejected) {
  const fs::path path = dir_ / "bad_shape";
  writeFlash(path, 3, makeTree(3, kLo, kHi), {.wrongShapeDens = true});
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              AllOf(HasSubstr(path.string()), HasSubstr("'dens'"), HasSubstr("shape [17, 4, 16]")));
}

TEST_F(FlashReader, ListedButAbsentVariableIsRejected) {
  const fs::path path = dir_ / "absent";
  writeFlash(path, 3, makeTree(3, kLo, kHi), {.listAbsentVariable = true});
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              AllOf(HasSubstr(path.string()), HasSubstr("'pres'"), HasSubstr("unknown names")));
}

TEST_F(FlashReader, BlockSizeInconsistentWithBoundingBoxIsRejected) {
  const fs::path path = dir_ / "bad_size";
  writeFlash(path, 3, makeTree(3, kLo, kHi), {.badBlockSize = true});
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              AllOf(HasSubstr(path.string()), HasSubstr("'block size'"), HasSubstr("block 4")));
}

// ---- what the file says about itself --------------------------------------------------------

TEST_F(FlashReader, WithoutParametersOnlyLevelsAreKnownAndUnitsAreFlashsDefaultCgs) {
  const fs::path path = dir_ / "bare";
  writeFlash(path, 3, makeTree(3, kLo, kHi));
  const DatasetInfo info = readFlash(path).info();
  EXPECT_EQ(info.format, "FLASH");
  EXPECT_FALSE(info.time.has_value());
  EXPECT_FALSE(info.periodicKnown);
  EXPECT_EQ(info.lengthUnit, "cm");
  EXPECT_EQ(info.timeUnit, "s");
  // Leaves at refine levels 2 and 3 (1 = root): our level 0 is refine level 3.
  EXPECT_EQ(info.fileLevel(0), 3);
  EXPECT_EQ(info.fileLevel(1), 2);
  EXPECT_THAT(info.levelName, HasSubstr("refine level (1 = root)"));
}

TEST_F(FlashReader, TimeUnitsAndPeriodicAxesComeFromScalarsAndRuntimeParameters) {
  const fs::path path = dir_ / "described";
  writeFlash(path, 3, makeTree(3, kLo, kHi));
  addMetadata(path, {{"dt", 0.01}, {"time", 2.5}},
              {{"xl_boundary_type", "periodic"},
               {"xr_boundary_type", "periodic"},
               {"yl_boundary_type", "outflow"},
               {"yr_boundary_type", "periodic"},
               {"zl_boundary_type", "periodic"},
               {"zr_boundary_type", "periodic"},
               {"pc_unitsbase", "MKS"}});
  const DatasetInfo info = readFlash(path).info();
  EXPECT_EQ(info.time, 2.5);
  EXPECT_EQ(info.timeUnit, "s");
  EXPECT_EQ(info.lengthUnit, "m");
  EXPECT_EQ(info.lengthUnitCentimetres, 100.0);
  EXPECT_TRUE(info.periodicKnown);
  // y is periodic on one face only: not periodic.
  EXPECT_THAT(info.periodic, ElementsAre(true, false, true));
}

TEST_F(FlashReader, TwoDimensionalFilesIgnoreTheZBoundary) {
  const fs::path path = dir_ / "flat_described";
  writeFlash(path, 2, makeTree(2, kLo, kHi));
  addMetadata(path, {},
              {{"xl_boundary_type", "outflow"},
               {"xr_boundary_type", "outflow"},
               {"yl_boundary_type", "periodic"},
               {"yr_boundary_type", "periodic"},
               {"zl_boundary_type", "periodic"},
               {"zr_boundary_type", "periodic"}});
  const DatasetInfo info = readFlash(path).info();
  EXPECT_TRUE(info.periodicKnown);
  EXPECT_THAT(info.periodic, ElementsAre(false, true, false));
}

void copyHalf(const fs::path& from, const fs::path& to) {
  std::ifstream in(from, std::ios::binary);
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(to, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 2));
}

TEST_F(FlashReader, TruncatedWrittenFileIsRejected) {
  const fs::path whole = dir_ / "whole", half = dir_ / "half";
  writeFlash(whole, 3, makeTree(3, kLo, kHi));
  copyHalf(whole, half);
  EXPECT_THAT(inputErrorOf([&] { readFlash(half); }), HasSubstr(half.string()));
}

TEST_F(FlashReader, MissingFileAndNonHdf5FileAreRejected) {
  EXPECT_THAT(inputErrorOf([&] { readFlash(dir_ / "nothing"); }),
              AllOf(HasSubstr((dir_ / "nothing").string()), HasSubstr("no such file")));
  const fs::path text = dir_ / "text";
  std::ofstream(text) << "not hdf5\n";
  EXPECT_THAT(inputErrorOf([&] { readFlash(text); }), HasSubstr(text.string()));
}

// ---- hardening: string storage, paths that are not files, declared sizes, values -----------

TEST_F(FlashReader, VariableNamesAreReadWhateverTheirStringStorage) {
  for (const NameStorage storage :
       {NameStorage::kNullPadded, NameStorage::kSpacePadded, NameStorage::kNullTerminated,
        NameStorage::kVariable, NameStorage::kExactWidth}) {
    const fs::path path = dir_ / ("names" + std::to_string(int(storage)));
    writeFlash(path, 3, makeTree(3, kLo, kHi), {.nameStorage = storage});
    const bricks::AmrField field = readFlash(path);
    std::vector<std::string> names;
    for (const auto& channel : field.channels()) names.push_back(channel.name);
    EXPECT_THAT(names, ElementsAre("velx", "vely", "velz", "dens")) << int(storage);
    EXPECT_EQ(field.cellCount(), 15u * 64u) << int(storage);
  }
}

// h5py writes a Python str as a variable-length string, in compound members too.
TEST_F(FlashReader, VariableLengthRuntimeParametersAreRead) {
  const fs::path path = dir_ / "vlen_parameters";
  writeFlash(path, 3, makeTree(3, kLo, kHi));
  struct Pair {
    const char* name;
    const char* value;
  };
  const hid_t file = H5Fopen(path.string().c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hid_t text = H5Tcopy(H5T_C_S1);
  H5Tset_size(text, H5T_VARIABLE);
  const hid_t type = H5Tcreate(H5T_COMPOUND, sizeof(Pair));
  H5Tinsert(type, "name", HOFFSET(Pair, name), text);
  H5Tinsert(type, "value", HOFFSET(Pair, value), text);
  const std::vector<Pair> pairs{{"yl_boundary_type", "periodic"},
                                {"yr_boundary_type", "periodic   "},
                                {"pc_unitsbase", "MKS"}};
  writeArray(file, "string runtime parameters", type, {pairs.size()}, pairs.data());
  H5Tclose(type);
  H5Tclose(text);
  H5Fclose(file);
  const DatasetInfo info = readFlash(path).info();
  EXPECT_THAT(info.periodic, ElementsAre(false, true, false));
  EXPECT_EQ(info.lengthUnit, "m");
}

TEST_F(FlashReader, DirectoriesAndFifosAreRefusedByNameBeforeOpening) {
  const fs::path directory = dir_ / "plt_dir";
  fs::create_directory(directory);
  EXPECT_THAT(inputErrorOf([&] { readFlash(directory); }),
              HasSubstr(directory.string() + ": is a directory, not a file"));
  const fs::path fifo = dir_ / "plt_fifo";
  testing::makeFifo(fifo);
  EXPECT_THAT(testing::inputErrorWithoutHanging(fifo, [&] { readFlash(fifo); }),
              HasSubstr(fifo.string() + ": is a FIFO (named pipe), not a regular file"));
}

// Replaces dataset `name` by a chunked one of shape `dims` whose chunks are never written: the
// file is small, the declared size huge.
void replaceWithUnwritten(const fs::path& path, const char* name, hid_t type,
                          const std::vector<hsize_t>& dims) {
  const hid_t file = H5Fopen(path.string().c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  ASSERT_GE(H5Ldelete(file, name, H5P_DEFAULT), 0);
  const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
  const hid_t create = H5Pcreate(H5P_DATASET_CREATE);
  const std::vector<hsize_t> chunk(dims.size(), 1);
  ASSERT_GE(H5Pset_chunk(create, int(chunk.size()), chunk.data()), 0);
  const hid_t set = H5Dcreate2(file, name, type, space, H5P_DEFAULT, create, H5P_DEFAULT);
  ASSERT_GE(set, 0);
  H5Dclose(set);
  H5Pclose(create);
  H5Sclose(space);
  H5Fclose(file);
}

TEST_F(FlashReader, DeclaredShapesAreCheckedAgainstTheStoredDataBeforeAllocating) {
  const fs::path path = dir_ / "huge";
  writeFlash(path, 3, makeTree(3, kLo, kHi));
  replaceWithUnwritten(path, "refine level", H5T_NATIVE_INT, {hsize_t{1} << 40});
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              AllOf(HasSubstr(path.string() + ": dataset 'refine level': declares 1099511627776 "
                                              "values, more than the 2147483648 accepted")));
  replaceWithUnwritten(path, "refine level", H5T_NATIVE_INT, {hsize_t{1} << 20});
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              HasSubstr("dataset 'refine level': declares 1048576 values of 4 bytes (4194304 "
                        "bytes) but the file stores 0 bytes"));

  writeFlash(path, 3, makeTree(3, kLo, kHi));
  replaceWithUnwritten(path, "dens", H5T_NATIVE_FLOAT, {17, 4, 4, 4});
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              HasSubstr("dataset 'dens': declares 1088 values of 4 bytes (4352 bytes) but the "
                        "file stores 0 bytes"));

  // Without `integer scalars` the block shape comes from the first variable: 4096^3 per block.
  writeFlash(path, 3, makeTree(3, kLo, kHi), {.omitScalars = true});
  for (const char* name : {"velx", "vely", "velz", "dens"})
    replaceWithUnwritten(path, name, H5T_NATIVE_DOUBLE, {17, 4096, 4096, 4096});
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              HasSubstr("dataset 'velx': declares 1168231104512 values, more than the "
                        "2147483648 accepted"));
}

// Rewrites one value of `name` (float64, [nb, nzb, nyb, nxb] = [17, 4, 4, 4]).
void setValue(const fs::path& path, const char* name, std::size_t block, int i, int j, int k,
              double value) {
  const hid_t file = H5Fopen(path.string().c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  std::vector<double> values = testing::readWholeDataset<double>(file, name, H5T_NATIVE_DOUBLE);
  values.at(block * 64 + (k * 4 + j) * 4 + i) = value;
  const hid_t set = H5Dopen2(file, name, H5P_DEFAULT);
  ASSERT_GE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Dclose(set);
  H5Fclose(file);
}

TEST_F(FlashReader, NonFiniteLeafValuesNameTheDatasetTheBlockAndTheCell) {
  const fs::path path = dir_ / "nan";
  writeFlash(path, 3, makeTree(3, kLo, kHi));
  // Block 0 is the root, a parent: its values become no cell and are not checked.
  setValue(path, "velx", 0, 0, 0, 0, std::nan(""));
  EXPECT_EQ(readFlash(path).cellCount(), 15u * 64u);
  setValue(path, "velx", 2, 3, 2, 1, std::nan(""));
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              HasSubstr(path.string() + ": dataset 'velx': value nan of block 2 cell (i, j, k) = "
                                        "(3, 2, 1) is not a number"));
  setValue(path, "velx", 2, 3, 2, 1, 1.0);
  setValue(path, "vely", 16, 0, 3, 2, 1e300);
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              HasSubstr("dataset 'vely': value 1e+300 of block 16 cell (i, j, k) = (0, 3, 2) is "
                        "beyond the float range"));
}

// A coarse 2D leaf and a fine one beside it, `levels` refine levels apart: the slab stacks each
// fine cell 2^levels times. Up to 256 copies per leaf cell are read, more are refused.
TEST_F(FlashReader, TwoDimensionalStackingIsBoundedByTheFilesCells) {
  const auto blocks = [](int levels) {
    const double fine = std::ldexp(1.0, -levels);
    return std::vector<Block>{{1, 1, {0, 0, 0}, {1, 1, 0}},
                              {1 + levels, 1, {1, 0, 0}, {1 + fine, fine, 0}}};
  };
  const fs::path path = dir_ / "deep_2d";
  writeFlash(path, 2, blocks(8));
  EXPECT_EQ(readFlash(path).cellCount(), 16u + 16u * 256u);
  writeFlash(path, 2, blocks(9));
  EXPECT_THAT(inputErrorOf([&] { readFlash(path); }),
              HasSubstr(path.string() + ": 32 leaf cells become more than 8192 cells after "
                                        "stacking 2D cells into a uniform slab: too many"));
}

// ---- the real 2D nanowire plotfile ----------------------------------------------------------

TEST_F(FlashReader, RealNanowirePlotfile) {
  if (!fs::exists(kRealFile)) GTEST_SKIP() << "real FLASH file absent: " << kRealFile;
  const bricks::AmrField field = readFlash(kRealFile);

  EXPECT_EQ(field.cellCount(), 65536u);
  EXPECT_EQ(field.finestLevel(), 0);
  EXPECT_EQ(field.coarsestLevel(), 0);
  EXPECT_EQ(field.bounds().lower, glm::ivec3(0, 0, 0));
  EXPECT_EQ(field.bounds().upper, glm::ivec3(256, 256, 1));  // 16x16 leaf blocks of 16x16
  std::vector<std::string> names;
  for (const auto& channel : field.channels()) names.push_back(channel.name);
  EXPECT_THAT(names, ElementsAre("dens", "depo", "pele", "prad", "tele", "tion", "trad", "cham",
                                 "targ", "sumy", "ye"));
  // Independent read of the file's bounding boxes, node types and dens.
  const hid_t file = H5Fopen(kRealFile.string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const auto dens = testing::readWholeDataset<float>(file, "dens", H5T_NATIVE_FLOAT);
  const auto bbox = testing::readWholeDataset<double>(file, "bounding box", H5T_NATIVE_DOUBLE);
  const auto nodeType = testing::readWholeDataset<int>(file, "node type", H5T_NATIVE_INT);
  H5Fclose(file);
  ASSERT_EQ(nodeType.size(), 341u);
  ASSERT_EQ(dens.size(), 341u * 256u);

  // Domain: the file's root block (its boxes hold float32-rounded -1e-4..1e-4 x 0..2e-3 cm).
  const auto& t = field.transform();
  const glm::dvec3 lower = t.toPhysical(glm::dvec3(field.bounds().lower));
  const glm::dvec3 upper = t.toPhysical(glm::dvec3(field.bounds().upper));
  EXPECT_NEAR(lower.x, bbox[0], 1e-18);
  EXPECT_NEAR(upper.x, bbox[1], 1e-18);
  EXPECT_NEAR(lower.y, bbox[2], 1e-18);
  EXPECT_NEAR(upper.y, bbox[3], 1e-17);
  EXPECT_NEAR(lower.x, -1e-4, 1e-11);
  EXPECT_NEAR(upper.x, 1e-4, 1e-11);
  EXPECT_NEAR(lower.y, 0.0, 1e-18);
  EXPECT_NEAR(upper.y, 2e-3, 1e-10);
  EXPECT_EQ(t.spacing.z, t.spacing.x);

  // dens[b][0][j][i] of a few leaf blocks lands on the cell at its centre.
  std::map<std::pair<int, int>, std::size_t> cellAt;
  for (std::size_t c = 0; c < field.cellCount(); ++c)
    cellAt[{field.lowers()[c].x, field.lowers()[c].y}] = c;
  std::vector<std::size_t> leaves;
  for (std::size_t b = 0; b < nodeType.size(); ++b)
    if (nodeType[b] == 1) leaves.push_back(b);
  ASSERT_EQ(leaves.size(), 256u);
  const auto& values = field.channel("dens").values;
  int checked = 0;
  for (std::size_t b : {leaves.front(), leaves[37], leaves[128], leaves[201], leaves.back()})
    for (auto [i, j] : {std::pair{0, 0}, {15, 15}, {3, 11}, {12, 2}}) {
      const glm::dvec3 centre(
          bbox[b * 6 + 0] + (i + 0.5) * (bbox[b * 6 + 1] - bbox[b * 6 + 0]) / 16,
          bbox[b * 6 + 2] + (j + 0.5) * (bbox[b * 6 + 3] - bbox[b * 6 + 2]) / 16, 0.0);
      const glm::dvec3 units = t.toCellUnits(centre);
      const auto it = cellAt.find({int(std::floor(units.x)), int(std::floor(units.y))});
      ASSERT_NE(it, cellAt.end()) << "block " << b << " cell " << i << "," << j;
      EXPECT_EQ(values[it->second], dens[b * 256 + j * 16 + i])
          << "block " << b << " cell " << i << "," << j;
      ++checked;
    }
  EXPECT_EQ(checked, 20);
}

// Oracle: `h5dump -m %.17g -d "real scalars"` and `-d "string runtime parameters"` on the file:
// time 1.0000117238534479e-09, pc_unitsbase "CGS", x boundaries periodic, y outflow, z periodic
// (ignored: the file is 2D); leaves at refine level 5 only (README).
TEST_F(FlashReader, RealNanowirePlotfileDescribesItself) {
  if (!fs::exists(kRealFile)) GTEST_SKIP() << "real FLASH file absent: " << kRealFile;
  const bricks::AmrField field = readFlash(kRealFile);
  const DatasetInfo& info = field.info();
  EXPECT_EQ(info.format, "FLASH");
  EXPECT_EQ(info.time, 1.0000117238534479e-09);
  EXPECT_EQ(info.timeUnit, "s");
  EXPECT_EQ(info.lengthUnit, "cm");
  EXPECT_TRUE(info.periodicKnown);
  EXPECT_THAT(info.periodic, ElementsAre(true, false, false));
  EXPECT_EQ(info.fileLevel(field.finestLevel()), 5);
}

TEST_F(FlashReader, TruncatedRealFileIsRejected) {
  if (!fs::exists(kRealFile)) GTEST_SKIP() << "real FLASH file absent: " << kRealFile;
  const fs::path half = dir_ / "nanowire_half";
  copyHalf(kRealFile, half);
  EXPECT_THAT(inputErrorOf([&] { readFlash(half); }), HasSubstr(half.string()));
}

}  // namespace
}  // namespace amrstream::formats
