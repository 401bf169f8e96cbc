// A 2D AMReX plotfile written here (two levels, ghost cells, two variables with known values) is
// read as 2D data: a slab across z = 0 as thick as a coarse cell, each fine cell repeated along z,
// every value that of its cell's centre in the plane; 1D plotfiles and 3D boxes in a 2D plotfile
// are refused naming the file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "amrstream/error.hpp"
#include "formats/amrex/amrex_reader.hpp"
#include "input_error_of.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

// Prob box (-1,0)-(1,2). Level 0: (0..7)^2, dx 0.25, one box. Level 1 (ratio 2): the coarse
// cells (2..5, 0..3), in one box. Each FAB stores one ghost cell around its box.
const glm::dvec2 kProbLo(-1.0, 0.0);
constexpr int kGhost = 1;
double valueA(glm::dvec2 p) { return 1.0 + p.x + 2.0 * p.y; }
double valueB(glm::dvec2 p, int level) { return p.x * p.y + 10.0 * level; }

struct Box2 {
  glm::ivec2 lo, hi;
};

std::string boxText(const Box2& b) {
  std::ostringstream out;
  out << "((" << b.lo.x << ',' << b.lo.y << ") (" << b.hi.x << ',' << b.hi.y << ") (0,0))";
  return out.str();
}

std::string fabBytes(const Box2& box, int level) {
  const Box2 stored{box.lo - kGhost, box.hi + kGhost};
  const double dx = 0.25 / (1 << level);
  std::string text =
      "FAB ((8, (64 11 52 0 1 12 0 1023)),(8, (8 7 6 5 4 3 2 1)))" + boxText(stored) + " 2\n";
  for (int c = 0; c < 2; ++c)
    for (int j = stored.lo.y; j <= stored.hi.y; ++j)
      for (int i = stored.lo.x; i <= stored.hi.x; ++i) {
        const glm::dvec2 p = kProbLo + (glm::dvec2(i, j) + 0.5) * dx;
        const double v = c == 0 ? valueA(p) : valueB(p, level);
        char bytes[8];  // the test host is little endian
        std::memcpy(bytes, &v, 8);
        text.append(bytes, 8);
      }
  return text;
}

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

void write2dPlotfile(const fs::path& dir) {
  const Box2 boxes[] = {{{0, 0}, {7, 7}}, {{4, 0}, {11, 7}}};
  std::ostringstream header;
  header << "HyperCLaw-V1.1\n2\nA\nB\n2\n0.5\n1\n-1 0\n1 2\n2\n"
         << "((0,0) (7,7) (0,0)) ((0,0) (15,15) (0,0))\n0 0\n0.25 0.25\n0.125 0.125\n0\n0\n";
  for (int level = 0; level < 2; ++level) {
    const double dx = 0.25 / (1 << level);
    const Box2& b = boxes[level];
    header << level << " 1 0.5\n0\n";
    for (int a = 0; a < 2; ++a)
      header << kProbLo[a] + b.lo[a] * dx << ' ' << kProbLo[a] + (b.hi[a] + 1) * dx << '\n';
    header << "Level_" << level << "/Cell\n";
    const fs::path levelDir = dir / ("Level_" + std::to_string(level));
    fs::create_directories(levelDir);
    writeFile(levelDir / "Cell_D_00000", fabBytes(b, level));
    writeFile(levelDir / "Cell_H", "1\n1\n2\n" + std::to_string(kGhost) + "\n(1 0\n" + boxText(b) +
                                       "\n)\n1\nFabOnDisk: Cell_D_00000 0\n");
  }
  writeFile(dir / "Header", header.str());
  writeFile(dir / "job_info", "geometry.is_periodic = 1 0\n");
}

class Amrex2d : public testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    write2dPlotfile(dir_);
  }
  void replaceIn(const fs::path& file, const std::string& from, const std::string& to) {
    std::ifstream in(file, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    writeFile(file, text);
  }
};

TEST_F(Amrex2d, IsReadAsASlabAcrossZeroWithEveryValueOfItsCell) {
  const bricks::AmrField field = readAmrexPlotfile(dir_);
  EXPECT_EQ(field.info().dimensions, 2);
  // The slab is one coarse cell (two fine cells) thick: 64 fine cells twice, and the 64 - 16
  // coarse cells the fine box leaves once.
  EXPECT_EQ(field.cellsPerLevel(), (std::vector<std::size_t>{128, 48}));
  EXPECT_EQ(field.transform().spacing, glm::dvec3(0.125));
  EXPECT_EQ(field.transform().origin, glm::dvec3(-1.0, 0.0, -0.125));
  EXPECT_TRUE(field.info().periodicKnown);
  EXPECT_TRUE(field.info().periodic[0]);
  EXPECT_FALSE(field.info().periodic[1]);
  EXPECT_FALSE(field.info().periodic[2]);

  const auto& a = field.channel("A").values;
  const auto& b = field.channel("B").values;
  double area = 0.0;
  for (std::size_t c = 0; c < field.cellCount(); ++c) {
    const int width = bricks::AmrField::cellWidth(field.levels()[c]);
    const glm::dvec3 centre =
        field.transform().toPhysical(glm::dvec3(field.lowers()[c]) + 0.5 * width);
    ASSERT_GT(centre.z, -0.125);
    ASSERT_LT(centre.z, 0.125);
    const int fileLevel = field.levels()[c] == 0 ? 1 : 0;
    const glm::dvec2 p(centre);
    ASSERT_EQ(a[c], static_cast<float>(valueA(p))) << "cell " << c;
    ASSERT_EQ(b[c], static_cast<float>(valueB(p, fileLevel))) << "cell " << c;
    const double side = width * 0.125;
    area += side * side * side / 0.25;  // the slab is 0.25 thick
  }
  EXPECT_DOUBLE_EQ(area, 4.0);  // the 2 x 2 plane, once
}

TEST_F(Amrex2d, OneDimensionalPlotfilesAreRefusedNamingTheHeader) {
  replaceIn(dir_ / "Header", "A\nB\n2\n", "A\nB\n1\n");
  EXPECT_THAT(testing::inputErrorOf([&] { readAmrexPlotfile(dir_); }),
              AllOf(HasSubstr((dir_ / "Header").string()), HasSubstr("1D")));
}

TEST_F(Amrex2d, AThreeDimensionalBoxInATwoDimensionalPlotfileIsRefused) {
  replaceIn(dir_ / "Level_1" / "Cell_H", "((4,0) (11,7) (0,0))", "((4,0,0) (11,7,0) (0,0,0))");
  EXPECT_THAT(testing::inputErrorOf([&] { readAmrexPlotfile(dir_); }),
              HasSubstr((dir_ / "Level_1" / "Cell_H").string()));
}

TEST_F(Amrex2d, PeriodicityWithThreeFlagsIsRefusedNamingJobInfo) {
  writeFile(dir_ / "job_info", "geometry.is_periodic = 1 0 1\n");
  EXPECT_THAT(testing::inputErrorOf([&] { readAmrexPlotfile(dir_); }),
              AllOf(HasSubstr("job_info:1"), HasSubstr("X Y")));
}

}  // namespace
}  // namespace amrstream::formats
