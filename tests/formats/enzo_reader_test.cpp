#include "formats/enzo/enzo_reader.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "hdf5_read.hpp"
#include "special_files.hpp"

namespace amrstream::formats {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

// ---- helpers independent of the reader ----

glm::dvec3 cellCentre(const bricks::AmrField& f, std::size_t c) {
  const double w = bricks::AmrField::cellWidth(f.levels()[c]);
  return f.transform().toPhysical(glm::dvec3(f.lowers()[c]) + 0.5 * w);
}

// Index of the leaf cell containing physical point p, or -1.
long findCell(const bricks::AmrField& f, glm::dvec3 p) {
  const glm::dvec3 u = f.transform().toCellUnits(p);
  for (std::size_t c = 0; c < f.cellCount(); ++c) {
    const glm::dvec3 lo(f.lowers()[c]);
    const double w = bricks::AmrField::cellWidth(f.levels()[c]);
    if (glm::all(glm::greaterThanEqual(u, lo)) && glm::all(glm::lessThan(u, lo + w)))
      return static_cast<long>(c);
  }
  return -1;
}

double leafVolume(const bricks::AmrField& f) {
  const glm::dvec3 s = f.transform().spacing;
  double v = 0;
  for (auto l : f.levels()) v += std::pow(double(bricks::AmrField::cellWidth(l)), 3);
  return v * s.x * s.y * s.z;
}

// ---- real data: DD0010/moving7_0010 ----

fs::path realDir() { return fs::path(AMRSTREAM_REAL_DATA_DIR) / "enzo-moving7" / "DD0010"; }

class EnzoRealTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(realDir() / "moving7_0010.cpu0000"))
      GTEST_SKIP() << "real Enzo data absent: " << realDir()
                   << " (shared/data/real not checked out)";
  }
};

TEST_F(EnzoRealTest, CellsPerLevelMatchTheGridTable) {
  const auto field = readEnzo(realDir() / "moving7_0010");
  // Independent oracle from the .harrays table: active cells minus those covered by children
  // (each child cell is 1/8 of a parent cell with RefineBy 2).
  const hid_t h =
      H5Fopen((realDir() / "moving7_0010.harrays").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(h, 0);
  const auto dims = testing::readWholeDataset<int>(h, "ActiveDimensions", H5T_NATIVE_INT);
  const auto level = testing::readWholeDataset<int>(h, "Level", H5T_NATIVE_INT);
  const auto parent = testing::readWholeDataset<int>(h, "ParentIDs", H5T_NATIVE_INT);
  H5Fclose(h);
  ASSERT_EQ(level.size(), 10u);
  std::vector<long> leaves(level.size());
  for (std::size_t g = 0; g < level.size(); ++g)
    leaves[g] = long(dims[3 * g]) * dims[3 * g + 1] * dims[3 * g + 2];
  for (std::size_t g = 0; g < level.size(); ++g)
    if (parent[g] > 0) {
      ASSERT_EQ(leaves[g] % 8, 0);
      leaves[parent[g] - 1] -= long(dims[3 * g]) * dims[3 * g + 1] * dims[3 * g + 2] / 8;
    }
  const int finest = *std::max_element(level.begin(), level.end());
  ASSERT_EQ(finest, 7);
  std::vector<std::size_t> expected(finest + 1, 0);
  for (std::size_t g = 0; g < level.size(); ++g) expected[finest - level[g]] += leaves[g];
  EXPECT_EQ(field.cellsPerLevel(), expected);
  EXPECT_NEAR(leafVolume(field), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(field.transform().spacing.x, 1.0 / 2048);
}

TEST_F(EnzoRealTest, EveryEntryPathGivesTheSameField) {
  const auto a = readEnzo(realDir() / "moving7_0010");
  const auto b = readEnzo(realDir() / "moving7_0010.hierarchy");
  const auto c = readEnzo(realDir() / "moving7_0010.harrays");
  EXPECT_EQ(a.cellCount(), b.cellCount());
  EXPECT_EQ(a.cellCount(), c.cellCount());
  EXPECT_EQ(a.cellsPerLevel(), b.cellsPerLevel());
}

TEST_F(EnzoRealTest, ChannelsAndBackgroundFlow) {
  const auto field = readEnzo(realDir() / "moving7_0010.hierarchy");
  for (const char* name : {"x-velocity", "y-velocity", "z-velocity", "Density"})
    EXPECT_TRUE(field.findChannel(name).has_value()) << name;
  for (const auto& c : field.channels()) EXPECT_FALSE(c.name.starts_with("particle_"));
  // A root cell far from the collapse (children start at 0.1875).
  const long c = findCell(field, {0.05, 0.05, 0.95});
  ASSERT_GE(c, 0);
  EXPECT_EQ(field.levels()[c], 7);
  for (const char* name : {"x-velocity", "y-velocity", "z-velocity"})
    EXPECT_NEAR(field.channel(name).values[c], 0.6, 0.02) << name;
}

TEST_F(EnzoRealTest, SpotValuesMatchTheHdf5Datasets) {
  const auto field = readEnzo(realDir() / "moving7_0010");
  const hid_t h =
      H5Fopen((realDir() / "moving7_0010.harrays").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const auto left = testing::readWholeDataset<double>(h, "LeftEdges", H5T_NATIVE_DOUBLE);
  const auto right = testing::readWholeDataset<double>(h, "RightEdges", H5T_NATIVE_DOUBLE);
  const auto dims = testing::readWholeDataset<int>(h, "ActiveDimensions", H5T_NATIVE_INT);
  H5Fclose(h);
  const hid_t f =
      H5Fopen((realDir() / "moving7_0010.cpu0000").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  struct Spot {
    int grid;  // 1-based
    int i, j, k;
    const char* name;
    int ourLevel;
  };
  // Root cell outside all children; the thin [2,10,10] grid 4 (no children); the finest grid.
  for (const Spot s : {Spot{1, 3, 2, 1, "x-velocity", 7}, Spot{1, 15, 0, 9, "Density", 7},
                       Spot{4, 1, 7, 3, "y-velocity", 6}, Spot{4, 0, 0, 9, "Density", 6},
                       Spot{10, 5, 4, 3, "z-velocity", 0}, Spot{10, 7, 9, 9, "x-velocity", 0}}) {
    const int g = s.grid - 1;
    const auto dataset = fmt::format("/Grid{:08d}/{}", s.grid, s.name);
    const auto values = testing::readWholeDataset<float>(f, dataset.c_str(), H5T_NATIVE_FLOAT);
    const int nx = dims[3 * g], ny = dims[3 * g + 1];
    const float expected = values[(std::size_t(s.k) * ny + s.j) * nx + s.i];
    glm::dvec3 p;
    const int idx[3] = {s.i, s.j, s.k};
    for (int a = 0; a < 3; ++a) {
      const double dx = (right[3 * g + a] - left[3 * g + a]) / dims[3 * g + a];
      p[a] = left[3 * g + a] + (idx[a] + 0.5) * dx;
    }
    const long c = findCell(field, p);
    ASSERT_GE(c, 0) << dataset;
    EXPECT_EQ(field.levels()[c], s.ourLevel) << dataset;
    EXPECT_EQ(field.channel(s.name).values[c], expected) << dataset;
  }
  H5Fclose(f);
}

// ---- a small Enzo-like dataset written here ----

struct SynthGrid {
  glm::dvec3 left, right;
  glm::ivec3 dims;
  int level;
  std::string file;  // field file basename
};

// Domain [0,1]^3, top grid 4^3. Grid 2 (level 1) covers part of the root, grid 3 (level 2,
// only 2 cells thick in y) part of grid 2, grid 4 (level 1, in a second file) another corner.
const std::vector<SynthGrid> kGrids = {
    {{0, 0, 0}, {1, 1, 1}, {4, 4, 4}, 0, "sim.cpu0000"},
    {{0.25, 0.25, 0.5}, {0.75, 0.75, 1.0}, {4, 4, 4}, 1, "sim.cpu0000"},
    {{0.5, 0.25, 0.5}, {0.75, 0.375, 0.75}, {4, 2, 4}, 2, "sim.cpu0000"},
    {{0.0, 0.0, 0.0}, {0.25, 0.5, 0.25}, {2, 4, 2}, 1, "sim.cpu0001"},
};
const std::vector<std::string> kFields = {"Density", "x-velocity", "y-velocity", "z-velocity"};

double analytic(int field, glm::dvec3 p) {
  switch (field) {
    case 0:
      return 1.0 + p.x + 2.0 * p.y + 3.0 * p.z;
    case 1:
      return std::sin(3.0 * p.y) + p.z;
    case 2:
      return p.x * p.z - 0.5;
    default:
      return std::cos(2.0 * p.x) * p.y;
  }
}

void writeFloats(hid_t group, const std::string& name, std::vector<hsize_t> shape,
                 const std::vector<float>& v) {
  const hid_t sp = H5Screate_simple(int(shape.size()), shape.data(), nullptr);
  const hid_t ds =
      H5Dcreate2(group, name.c_str(), H5T_IEEE_F32BE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(ds, 0);
  ASSERT_GE(H5Dwrite(ds, H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0);
  H5Dclose(ds);
  H5Sclose(sp);
}

void writeSynthetic(const fs::path& dir) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "sim") << "TopGridRank = 3\nTopGridDimensions = 4 4 4\nRefineBy = 2\n"
                                "DomainLeftEdge = 0 0 0\nDomainRightEdge = 1 1 1\n";
  std::ofstream h(dir / "sim.hierarchy");
  const int next[] = {0, 4, 0, 0}, nextLevel[] = {2, 3, 0, 0};
  std::map<std::string, hid_t> files;
  for (std::size_t n = 0; n < kGrids.size(); ++n) {
    const auto& g = kGrids[n];
    h << "\nGrid = " << n + 1 << "\nGridRank          = 3\n"
      << "GridDimension     = " << g.dims.x + 6 << ' ' << g.dims.y + 6 << ' ' << g.dims.z + 6
      << " \nGridStartIndex    = 3 3 3 \nGridEndIndex      = " << g.dims.x + 2 << ' '
      << g.dims.y + 2 << ' ' << g.dims.z + 2 << " \nGridLeftEdge      = " << g.left.x << ' '
      << g.left.y << ' ' << g.left.z << " \nGridRightEdge     = " << g.right.x << ' ' << g.right.y
      << ' ' << g.right.z << " \nNumberOfBaryonFields = 4\n"
      << "BaryonFileName = /elsewhere/run/DD0001/" << g.file << "\n"
      << "Pointer: Grid[" << n + 1 << "]->NextGridThisLevel = " << next[n] << "\n"
      << "Pointer: Grid[" << n + 1 << "]->NextGridNextLevel = " << nextLevel[n] << "\n";
    if (!files.contains(g.file))
      files[g.file] = H5Fcreate((dir / g.file).c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    const hid_t grp = H5Gcreate2(files[g.file], fmt::format("Grid{:08d}", n + 1).c_str(),
                                 H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const glm::dvec3 dx = (g.right - g.left) / glm::dvec3(g.dims);
    for (std::size_t f = 0; f < kFields.size(); ++f) {
      std::vector<float> v;
      for (int k = 0; k < g.dims.z; ++k)
        for (int j = 0; j < g.dims.y; ++j)
          for (int i = 0; i < g.dims.x; ++i)
            v.push_back(float(analytic(int(f), g.left + (glm::dvec3(i, j, k) + 0.5) * dx)));
      writeFloats(grp, kFields[f], {hsize_t(g.dims.z), hsize_t(g.dims.y), hsize_t(g.dims.x)}, v);
    }
    writeFloats(grp, "particle_mass", {3}, {1.f, 2.f, 3.f});
    H5Gclose(grp);
  }
  for (auto& [name, id] : files) H5Fclose(id);
}

class EnzoSyntheticTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) /
           fmt::format("enzo_{}", ::testing::UnitTest::GetInstance()->current_test_info()->name());
    writeSynthetic(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Opens `file` in dir_ for editing one grid group.
  template <typename Edit>
  void editGroup(const std::string& file, int grid, Edit edit) {
    const hid_t f = H5Fopen((dir_ / file).c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const hid_t g = H5Gopen2(f, fmt::format("Grid{:08d}", grid).c_str(), H5P_DEFAULT);
    ASSERT_GE(g, 0);
    edit(g);
    H5Gclose(g);
    H5Fclose(f);
  }

  void expectRejected(const fs::path& entry, const std::string& fileInMessage,
                      const std::string& detail) {
    try {
      readEnzo(entry);
      ADD_FAILURE() << "accepted a corrupted copy (" << detail << ")";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), HasSubstr(fileInMessage));
      EXPECT_THAT(e.what(), HasSubstr(detail));
    }
  }

  // Replaces the first `from` in `file` (in dir_) by `to`.
  void replaceText(const std::string& file, const std::string& from, const std::string& to) {
    std::ifstream in(dir_ / file);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream(dir_ / file) << text;
  }

  fs::path dir_;
};

TEST_F(EnzoSyntheticTest, EveryLeafValueAndCoveredCellsDropped) {
  const auto field = readEnzo(dir_ / "sim");
  // finest level 2: grid 3 = 32; level 1: grid 2 (64 - 2*1*2 covered) + grid 4 (16) = 76;
  // root: 64 - 2*2*2 (grid 2) - 1*2*1 (grid 4) = 54.
  EXPECT_EQ(field.cellsPerLevel(), (std::vector<std::size_t>{32, 76, 54}));
  EXPECT_NEAR(leafVolume(field), 1.0, 1e-12);
  EXPECT_EQ(field.transform().spacing, glm::dvec3(1.0 / 16));
  EXPECT_EQ(field.transform().origin, glm::dvec3(0.0));
  ASSERT_EQ(field.channels().size(), kFields.size());
  for (std::size_t f = 0; f < kFields.size(); ++f) {
    const auto& values = field.channel(kFields[f]).values;
    for (std::size_t c = 0; c < field.cellCount(); ++c)
      ASSERT_EQ(values[c], float(analytic(int(f), cellCentre(field, c))))
          << kFields[f] << " cell " << c;
  }
  // A root cell under grid 2 is gone: the point is in a level-1 cell (our level 1).
  EXPECT_EQ(field.levels()[findCell(field, {0.3, 0.3, 0.6})], 1);
  EXPECT_EQ(field.levels()[findCell(field, {0.6, 0.3, 0.6})], 0);
  EXPECT_EQ(field.levels()[findCell(field, {0.9, 0.9, 0.1})], 2);
}

TEST_F(EnzoSyntheticTest, WorksWithoutTheParameterFile) {
  fs::remove(dir_ / "sim");
  const auto field = readEnzo(dir_ / "sim.hierarchy");
  EXPECT_EQ(field.cellsPerLevel(), (std::vector<std::size_t>{32, 76, 54}));
}

TEST_F(EnzoSyntheticTest, RejectsAMissingDataset) {
  editGroup("sim.cpu0000", 3,
            [](hid_t g) { ASSERT_GE(H5Ldelete(g, "x-velocity", H5P_DEFAULT), 0); });
  expectRejected(dir_ / "sim", (dir_ / "sim.cpu0000").string(), "Grid00000003/x-velocity");
}

TEST_F(EnzoSyntheticTest, RejectsADatasetWithTheWrongShape) {
  editGroup("sim.cpu0000", 2, [](hid_t g) {
    ASSERT_GE(H5Ldelete(g, "Density", H5P_DEFAULT), 0);
    writeFloats(g, "Density", {4, 4, 3}, std::vector<float>(48, 1.f));
  });
  expectRejected(dir_ / "sim", (dir_ / "sim.cpu0000").string(), "Grid00000002/Density");
}

TEST_F(EnzoSyntheticTest, RejectsATruncatedHierarchy) {
  const auto path = dir_ / "sim.hierarchy";
  for (double keep : {0.3, 0.6, 0.97}) {
    writeSynthetic(dir_);
    fs::resize_file(path, static_cast<std::uintmax_t>(keep * fs::file_size(path)));
    expectRejected(dir_ / "sim", path.string(), "truncated");
  }
}

// Grids 3 and 4 each cover half of a coarser cell (grid 2's and the root's): the error names
// the first covered grid in the table's order, the root, whichever is checked first.
TEST_F(EnzoSyntheticTest, AGridCoveringPartOfACoarserCellIsNamedInTableOrder) {
  replaceText("sim.hierarchy", "0.5 0.25 0.5 \nGridRightEdge     = 0.75 0.375 0.75",
              "0.5625 0.25 0.5 \nGridRightEdge     = 0.8125 0.375 0.75");
  replaceText("sim.hierarchy", "0 0 0 \nGridRightEdge     = 0.25 0.5 0.25",
              "0.125 0 0 \nGridRightEdge     = 0.375 0.5 0.25");
  expectRejected(dir_ / "sim", (dir_ / "sim.hierarchy").string(),
                 "grid 4 covers only part of a cell of grid 1");
}

TEST_F(EnzoSyntheticTest, RejectsAMissingGridFile) {
  fs::remove(dir_ / "sim.cpu0001");
  expectRejected(dir_ / "sim.hierarchy", (dir_ / "sim.cpu0001").string(), "grid 4");
}

TEST_F(EnzoSyntheticTest, RejectsAMissingGridGroup) {
  const hid_t f = H5Fopen((dir_ / "sim.cpu0000").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(H5Ldelete(f, "Grid00000002", H5P_DEFAULT), 0);
  H5Fclose(f);
  expectRejected(dir_ / "sim", (dir_ / "sim.cpu0000").string(), "Grid00000002");
}

TEST_F(EnzoSyntheticTest, RejectsAbsentInput) {
  expectRejected(dir_ / "nothing", (dir_ / "nothing").string(), "no such file");
  fs::remove(dir_ / "sim.hierarchy");
  expectRejected(dir_ / "sim", (dir_ / "sim").string(), "sim.hierarchy");
}

// ---- hardening: numbers from text, overflow, declared sizes, paths that are not files -------

TEST_F(EnzoSyntheticTest, NumbersFromTextFilesAreNamedWhenMalformed) {
  replaceText("sim", "RefineBy = 2", "RefineBy = two");
  expectRejected(dir_ / "sim", (dir_ / "sim").string(),
                 "RefineBy is not an integer in [1, 1073741824]: 'two'");
  writeSynthetic(dir_);
  replaceText("sim.hierarchy", "Grid = 2\nGridRank          = 3",
              "Grid = 2\nGridRank = 3\nLevel = one");
  expectRejected(dir_ / "sim", (dir_ / "sim.hierarchy").string(),
                 "grid 2 Level is not an integer in [0, 2147483647]: 'one'");
  writeSynthetic(dir_);
  replaceText("sim.hierarchy", "GridLeftEdge      = 0.25", "GridLeftEdge      = 0.2.5");
  expectRejected(dir_ / "sim", (dir_ / "sim.hierarchy").string(),
                 "grid 2 GridLeftEdge is not a finite number: '0.2.5'");
  writeSynthetic(dir_);
  replaceText("sim.hierarchy", "Pointer: Grid[3]->NextGridThisLevel = 0",
              "Pointer: Grid[3]->NextGridThisLevel = 99999999999");
  expectRejected(dir_ / "sim", (dir_ / "sim.hierarchy").string() + ":",
                 "a pointer's target grid is not an integer in [0, 2147483647]: '99999999999'");
}

TEST_F(EnzoSyntheticTest, IndicesNearIntMinAndMaxAreRefusedWithoutOverflow) {
  replaceText("sim.hierarchy", "GridStartIndex    = 3 3 3", "GridStartIndex    = -2147483648 3 3");
  expectRejected(dir_ / "sim", (dir_ / "sim.hierarchy").string(),
                 "grid 1 GridStartIndex is not an integer in [0, 2147483647]: '-2147483648'");
  writeSynthetic(dir_);
  replaceText(
      "sim.hierarchy",
      "GridDimension     = 10 10 10 \nGridStartIndex    = 3 3 3 \nGridEndIndex      = 6 6 6",
      "GridDimension     = 2147483647 10 10 \nGridStartIndex    = 0 3 3 \nGridEndIndex      = "
      "2147483646 6 6");
  expectRejected(dir_ / "sim", (dir_ / "sim.hierarchy").string(),
                 "grid 1 has 2147483647 active zones along axis x (expected 1 to 1073741824)");
}

// The grid table claims a 2^20-cubed root grid: refused before anything is allocated for it.
TEST_F(EnzoSyntheticTest, AHugeRootGridIsRefusedBeforeAllocating) {
  replaceText("sim", "TopGridDimensions = 4 4 4", "TopGridDimensions = 1048576 1048576 1048576");
  replaceText(
      "sim.hierarchy",
      "GridDimension     = 10 10 10 \nGridStartIndex    = 3 3 3 \nGridEndIndex      = 6 6 6",
      "GridDimension     = 1048582 1048582 1048582 \nGridStartIndex    = 3 3 3 \n"
      "GridEndIndex      = 1048578 1048578 1048578");
  expectRejected(dir_ / "sim", (dir_ / "sim.hierarchy").string(),
                 "grid 1 has 1048576 x 1048576 x 1048576 = 1152921504606846976 active zones, "
                 "more than the 2147483648 accepted");
}

TEST_F(EnzoSyntheticTest, FieldsWhoseDeclaredSizeTheFileDoesNotStoreAreRefused) {
  editGroup("sim.cpu0000", 2, [](hid_t g) {
    ASSERT_GE(H5Ldelete(g, "Density", H5P_DEFAULT), 0);
    const hsize_t dims[3] = {4, 4, 4}, chunk[3] = {1, 1, 1};
    const hid_t space = H5Screate_simple(3, dims, nullptr);
    const hid_t create = H5Pcreate(H5P_DATASET_CREATE);
    H5Pset_chunk(create, 3, chunk);
    const hid_t set =
        H5Dcreate2(g, "Density", H5T_IEEE_F32BE, space, H5P_DEFAULT, create, H5P_DEFAULT);
    ASSERT_GE(set, 0);
    H5Dclose(set);
    H5Pclose(create);
    H5Sclose(space);
  });
  expectRejected(dir_ / "sim", (dir_ / "sim.cpu0000").string(),
                 "dataset '/Grid00000002/Density': declares 64 values of 4 bytes (256 bytes) but "
                 "the file stores 0 bytes");
}

TEST_F(EnzoSyntheticTest, NonFiniteValuesNameTheDatasetAndTheZone) {
  editGroup("sim.cpu0001", 4, [](hid_t g) {
    ASSERT_GE(H5Ldelete(g, "Density", H5P_DEFAULT), 0);
    std::vector<float> values(16, 1.0f);
    values[(1 * 4 + 2) * 2 + 0] = std::numeric_limits<float>::infinity();  // (i, j, k) = (0, 2, 1)
    writeFloats(g, "Density", {2, 4, 2}, values);
  });
  expectRejected(dir_ / "sim", (dir_ / "sim.cpu0001").string(),
                 "dataset /Grid00000004/Density: value inf at zone (i, j, k) = (0, 2, 1) is "
                 "infinite");
}

TEST_F(EnzoSyntheticTest, DirectoriesAndFifosAreRefusedByNameBeforeOpening) {
  fs::remove(dir_ / "sim.cpu0001");
  fs::create_directory(dir_ / "sim.cpu0001");
  expectRejected(dir_ / "sim", (dir_ / "sim.cpu0001").string(), "is a directory, not a file");

  writeSynthetic(dir_);
  fs::remove(dir_ / "sim.hierarchy");
  testing::makeFifo(dir_ / "sim.hierarchy");
  EXPECT_THAT(
      testing::inputErrorWithoutHanging(dir_ / "sim.hierarchy", [&] { readEnzo(dir_ / "sim"); }),
      HasSubstr((dir_ / "sim.hierarchy").string() + ": is a FIFO"));

  writeSynthetic(dir_);
  fs::remove(dir_ / "sim");
  testing::makeFifo(dir_ / "sim");
  EXPECT_THAT(
      testing::inputErrorWithoutHanging(dir_ / "sim", [&] { readEnzo(dir_ / "sim.hierarchy"); }),
      HasSubstr((dir_ / "sim").string() + ": is a FIFO"));
}

}  // namespace
}  // namespace amrstream::formats
