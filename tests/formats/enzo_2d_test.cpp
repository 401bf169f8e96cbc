// A 2D Enzo dataset written here (TopGridRank 2, a root grid and a refined grid, two fields with
// known values) is read as 2D data: a slab across z = 0 as thick as a root cell, each fine cell
// repeated along z, every value that of its cell's centre in the plane. Both ways of writing the
// hierarchy (two numbers per axis list, or three with a one-zone z) and both dataset shapes
// ((ny, nx) and (1, ny, nx)) are read; a rank that the parameter file and the hierarchy disagree
// on, and a dataset of several z zones, are refused naming the file.

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/enzo/enzo_reader.hpp"
#include "input_error_of.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

// Domain (0,0)-(2,1), root grid 8 x 8 (cells 0.25 x 0.125); grid 2 (level 1) refines the root
// cells (2..5, 2..5).
struct Grid2 {
  glm::dvec2 left, right;
  glm::ivec2 zones;
};
const Grid2 kGrids[] = {{{0.0, 0.0}, {2.0, 1.0}, {8, 8}}, {{0.5, 0.25}, {1.5, 0.75}, {8, 8}}};
const char* const kFields[] = {"Density", "x-velocity"};

double analytic(int field, glm::dvec2 p) {
  return field == 0 ? 1.0 + p.x + 2.0 * p.y : p.x * p.y - 0.5;
}

// `padded`: the hierarchy lists three numbers per axis list and the datasets are (1, ny, nx).
void write2dEnzo(const fs::path& dir, bool padded) {
  std::ofstream(dir / "sim") << "TopGridRank = 2\nTopGridDimensions = 8 8\nRefineBy = 2\n"
                                "DomainLeftEdge = 0 0\nDomainRightEdge = 2 1\n"
                                "LeftFaceBoundaryCondition = 3 0\n"
                                "RightFaceBoundaryCondition = 3 0\n";
  std::ofstream h(dir / "sim.hierarchy");
  const hid_t file =
      H5Fcreate((dir / "sim.cpu0000").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (int n = 0; n < 2; ++n) {
    const Grid2& g = kGrids[n];
    const auto three = [padded](const std::string& xy, const std::string& z) {
      return padded ? xy + " " + z : xy;
    };
    h << "\nGrid = " << n + 1 << "\nGridRank = 2\n"
      << "GridDimension = " << three(fmt::format("{} {}", g.zones.x + 6, g.zones.y + 6), "1")
      << "\nGridStartIndex = " << three("3 3", "0")
      << "\nGridEndIndex = " << three(fmt::format("{} {}", g.zones.x + 2, g.zones.y + 2), "0")
      << "\nGridLeftEdge = " << three(fmt::format("{} {}", g.left.x, g.left.y), "0")
      << "\nGridRightEdge = " << three(fmt::format("{} {}", g.right.x, g.right.y), "1")
      << "\nNumberOfBaryonFields = 2\nBaryonFileName = sim.cpu0000\n"
      << "Pointer: Grid[" << n + 1 << "]->NextGridThisLevel = 0\n"
      << "Pointer: Grid[" << n + 1 << "]->NextGridNextLevel = " << (n == 0 ? 2 : 0) << "\n";
    const hid_t group = H5Gcreate2(file, fmt::format("Grid{:08d}", n + 1).c_str(), H5P_DEFAULT,
                                   H5P_DEFAULT, H5P_DEFAULT);
    const glm::dvec2 dx = (g.right - g.left) / glm::dvec2(g.zones);
    std::vector<hsize_t> shape{hsize_t(g.zones.y), hsize_t(g.zones.x)};
    if (padded) shape.insert(shape.begin(), 1);
    for (int f = 0; f < 2; ++f) {
      std::vector<double> values;
      for (int j = 0; j < g.zones.y; ++j)
        for (int i = 0; i < g.zones.x; ++i)
          values.push_back(analytic(f, g.left + (glm::dvec2(i, j) + 0.5) * dx));
      const hid_t space = H5Screate_simple(int(shape.size()), shape.data(), nullptr);
      const hid_t set = H5Dcreate2(group, kFields[f], H5T_IEEE_F64LE, space, H5P_DEFAULT,
                                   H5P_DEFAULT, H5P_DEFAULT);
      ASSERT_GE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
      H5Dclose(set);
      H5Sclose(space);
    }
    H5Gclose(group);
  }
  H5Fclose(file);
}

class Enzo2d : public testing::TempDirTest, public ::testing::WithParamInterface<bool> {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    write2dEnzo(dir_, GetParam());
  }
  void replaceIn(const std::string& name, const std::string& from, const std::string& to) {
    std::ifstream in(dir_ / name);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream(dir_ / name) << text;
  }
};

TEST_P(Enzo2d, IsReadAsASlabAcrossZeroWithEveryValueOfItsCell) {
  const bricks::AmrField field = readEnzo(dir_ / "sim");
  EXPECT_EQ(field.info().dimensions, 2);
  // The slab is one root cell (two fine cells) thick: 64 fine cells twice, and the 64 - 16 root
  // cells that grid 2 leaves once.
  EXPECT_EQ(field.cellsPerLevel(), (std::vector<std::size_t>{128, 48}));
  EXPECT_EQ(field.transform().spacing, glm::dvec3(0.125, 0.0625, 0.125));
  EXPECT_EQ(field.transform().origin, glm::dvec3(0.0, 0.0, -0.125));
  EXPECT_TRUE(field.info().periodic[0]);
  EXPECT_FALSE(field.info().periodic[1]);
  EXPECT_FALSE(field.info().periodic[2]);

  double area = 0.0;
  for (std::size_t c = 0; c < field.cellCount(); ++c) {
    const int width = bricks::AmrField::cellWidth(field.levels()[c]);
    const glm::dvec3 centre =
        field.transform().toPhysical(glm::dvec3(field.lowers()[c]) + 0.5 * width);
    ASSERT_GT(centre.z, -0.125);
    ASSERT_LT(centre.z, 0.125);
    for (int f = 0; f < 2; ++f)
      ASSERT_EQ(field.channel(kFields[f]).values[c],
                static_cast<float>(analytic(f, glm::dvec2(centre))))
          << kFields[f] << " cell " << c;
    area += width * 0.125 * width * 0.0625 * (width * 0.125 / 0.25);
  }
  EXPECT_DOUBLE_EQ(area, 2.0);  // the 2 x 1 plane, once
}

TEST_P(Enzo2d, ARankTheParameterFileAndHierarchyDisagreeOnIsRefused) {
  replaceIn("sim", "TopGridRank = 2\nTopGridDimensions = 8 8\n",
            "TopGridRank = 3\nTopGridDimensions = 8 8 1\n");
  replaceIn("sim", "DomainLeftEdge = 0 0\nDomainRightEdge = 2 1\n",
            "DomainLeftEdge = 0 0 0\nDomainRightEdge = 2 1 1\n");
  EXPECT_THAT(
      testing::inputErrorOf([&] { readEnzo(dir_ / "sim"); }),
      AllOf(HasSubstr("sim.hierarchy"), HasSubstr("GridRank 2"), HasSubstr("TopGridRank 3")));
}

TEST_P(Enzo2d, ADatasetOfSeveralZZonesIsRefusedNamingIt) {
  const hid_t file = H5Fopen((dir_ / "sim.cpu0000").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  ASSERT_GE(H5Ldelete(file, "Grid00000002/Density", H5P_DEFAULT), 0);
  const hsize_t shape[] = {2, 8, 8};
  const std::vector<double> zeros(128, 0.0);
  const hid_t space = H5Screate_simple(3, shape, nullptr);
  const hid_t set = H5Dcreate2(file, "Grid00000002/Density", H5T_IEEE_F64LE, space, H5P_DEFAULT,
                               H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data());
  H5Dclose(set);
  H5Sclose(space);
  H5Fclose(file);
  EXPECT_THAT(
      testing::inputErrorOf([&] { readEnzo(dir_ / "sim"); }),
      AllOf(HasSubstr("sim.cpu0000"), HasSubstr("/Grid00000002/Density"), HasSubstr("(ny,nx)")));
}

TEST_P(Enzo2d, OneDimensionalDataIsRefusedNamingTheParameterFile) {
  replaceIn("sim", "TopGridRank = 2", "TopGridRank = 1");
  EXPECT_THAT(testing::inputErrorOf([&] { readEnzo(dir_ / "sim"); }),
              AllOf(HasSubstr((dir_ / "sim").string()), HasSubstr("1D")));
}

INSTANTIATE_TEST_SUITE_P(HierarchyLists, Enzo2d, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "padded" : "twoNumbers"; });

}  // namespace
}  // namespace amrstream::formats
