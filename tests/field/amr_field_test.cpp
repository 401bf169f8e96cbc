// AmrField construction: valid layouts are accepted with the right bounds and counts; every kind
// of inconsistency is rejected with an error naming the source and the problem.

#include "bricks/amr_field.hpp"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "input_error_of.hpp"
#include "random_amr.hpp"

namespace amrstream::bricks {
namespace {

using ::testing::AnyOf;
using ::testing::HasSubstr;

AmrField makeField(std::vector<glm::ivec3> lowers, std::vector<std::uint8_t> levels,
                   std::vector<float> values = {}) {
  if (values.empty()) values.assign(lowers.size(), 1.0f);
  return AmrField(std::move(lowers), std::move(levels), {{"rho", values}}, {}, "test.exa");
}

TEST(AmrField, AcceptsTwoLevelLayoutAndReportsBoundsAndCounts) {
  // A level-1 cell at the origin next to eight level-0 cells filling the neighbouring cell.
  std::vector<glm::ivec3> lowers{{0, 0, 0}};
  std::vector<std::uint8_t> levels{1};
  for (int i = 0; i < 8; ++i) {
    lowers.push_back(glm::ivec3(2 + (i & 1), (i >> 1) & 1, (i >> 2) & 1));
    levels.push_back(0);
  }
  const AmrField field = makeField(lowers, levels);
  EXPECT_EQ(field.cellCount(), 9u);
  EXPECT_EQ(field.bounds().lower, glm::ivec3(0));
  EXPECT_EQ(field.bounds().upper, glm::ivec3(4, 2, 2));
  EXPECT_EQ(field.cellsPerLevel(), (std::vector<std::size_t>{8, 1}));
  EXPECT_EQ(field.finestLevel(), 0);
  EXPECT_EQ(field.coarsestLevel(), 1);
}

TEST(AmrField, AcceptsRandomLayoutsWhoseVolumesTileTheRootGrid) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    testing::RandomAmrOptions options;
    options.origin = glm::ivec3(-16, 8, 0);
    const AmrField field = testing::randomAmr(seed, options);
    std::int64_t volume = 0;
    for (std::uint8_t level : field.levels()) volume += std::int64_t(1) << (3 * level);
    EXPECT_EQ(volume, 27 * 512) << "seed " << seed;  // 3^3 root cells of width 8
  }
}

TEST(AmrField, RejectsDuplicateCells) {
  EXPECT_THAT(testing::inputErrorOf([] {
                makeField({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}, {0, 0, 0});
              }),
              HasSubstr("appears twice"));
}

TEST(AmrField, RejectsFineCellInsideCoarseCell) {
  const std::string error = testing::inputErrorOf([] {
    makeField({{4, 4, 4}, {5, 6, 7}}, {2, 0});
  });
  EXPECT_THAT(error, HasSubstr("test.exa"));
  EXPECT_THAT(error, HasSubstr("overlaps the level-2 cell at 4,4,4"));
}

// A cell listed right after a neighbour of its level looks only at the coarser levels where their
// corners differ (the rest the neighbour looked at): (0,0,0) and (2,0,0) differ below level 2,
// (4,0,0) and (2,1,0) below level 3.
TEST(AmrField, RejectsFineCellInsideCoarseCellAfterAFineNeighbour) {
  EXPECT_THAT(testing::inputErrorOf([] {
                makeField({{0, 0, 0}, {2, 0, 0}, {2, 0, 0}}, {0, 0, 1});
              }),
              HasSubstr("cell 1 (level 0, lower corner 2,0,0) overlaps the level-1 cell at 2,0,0"));
  EXPECT_THAT(testing::inputErrorOf([] {
                makeField({{4, 0, 0}, {2, 1, 0}, {0, 0, 0}}, {0, 0, 2});
              }),
              HasSubstr("cell 1 (level 0, lower corner 2,1,0) overlaps the level-2 cell at 0,0,0"));
}

// Many cells in shuffled order: tiles of a level's set are shared by cells far apart in the
// input, inserted by different threads. Every added duplicate or nested cell is found, and named
// as the first failing cell in input order.
TEST(AmrField, FindsDuplicatesAndNestedCellsAmongManyShuffledCells) {
  testing::RandomAmrOptions options;
  options.rootCells = glm::ivec3(6, 5, 4);
  options.origin = glm::ivec3(-24, 8, -16);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const AmrField field = testing::randomAmr(seed, options);
    std::vector<glm::ivec3> lowers(field.lowers().begin(), field.lowers().end());
    std::vector<std::uint8_t> levels(field.levels().begin(), field.levels().end());
    std::vector<std::size_t> order(lowers.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::mt19937_64 random(seed);
    std::shuffle(order.begin(), order.end(), random);
    std::vector<glm::ivec3> shuffledLowers;
    std::vector<std::uint8_t> shuffledLevels;
    for (std::size_t i : order) {
      shuffledLowers.push_back(lowers[i]);
      shuffledLevels.push_back(levels[i]);
    }
    EXPECT_NO_THROW(makeField(shuffledLowers, shuffledLevels)) << "seed " << seed;

    const std::size_t n = shuffledLowers.size();
    const std::size_t copied = random() % n;
    std::vector<glm::ivec3> twice = shuffledLowers;
    std::vector<std::uint8_t> twiceLevels = shuffledLevels;
    twice.insert(twice.begin() + n / 2, shuffledLowers[copied]);
    twiceLevels.insert(twiceLevels.begin() + n / 2, shuffledLevels[copied]);
    // Either of the two may be the one found already present.
    const std::size_t original = copied < n / 2 ? copied : copied + 1;
    const std::string error = testing::inputErrorOf([&] { makeField(twice, twiceLevels); });
    EXPECT_THAT(error, HasSubstr("appears twice"));
    EXPECT_THAT(error, AnyOf(HasSubstr(fmt::format("cell {} ", n / 2)),
                             HasSubstr(fmt::format("cell {} ", original))))
        << "seed " << seed;

    std::size_t coarse = 0;
    while (shuffledLevels[coarse] == 0) ++coarse;
    const int width = 1 << shuffledLevels[coarse];
    std::vector<glm::ivec3> nested = shuffledLowers;
    std::vector<std::uint8_t> nestedLevels = shuffledLevels;
    nested.push_back(shuffledLowers[coarse] + glm::ivec3(width - 1, 0, width / 2));
    nestedLevels.push_back(0);
    const glm::ivec3 at = shuffledLowers[coarse];
    EXPECT_THAT(testing::inputErrorOf([&] { makeField(nested, nestedLevels); }),
                HasSubstr(fmt::format("cell {} (level 0, lower corner {},{},{}) overlaps the "
                                      "level-{} cell at {},{},{}",
                                      n, at.x + width - 1, at.y, at.z + width / 2,
                                      int(shuffledLevels[coarse]), at.x, at.y, at.z)))
        << "seed " << seed;
  }
}

TEST(AmrField, RejectsOverlapAcrossNegativeCoordinates) {
  EXPECT_THAT(testing::inputErrorOf([] {
                makeField({{-4, -4, -4}, {-1, -3, -2}}, {2, 0});
              }),
              HasSubstr("overlaps the level-2 cell at -4,-4,-4"));
}

TEST(AmrField, RejectsMisalignedCell) {
  EXPECT_THAT(
      testing::inputErrorOf([] {
        makeField({{2, 0, 0}}, {2});
      }),
      HasSubstr("not aligned to its level's grid (corner coordinates must be multiples of 4)"));
}

TEST(AmrField, RejectsNonFiniteValues) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_THAT(testing::inputErrorOf([&] {
                makeField({{0, 0, 0}, {1, 0, 0}}, {0, 0}, {1.0f, nan});
              }),
              HasSubstr("channel 'rho' has a non-finite value (nan) at cell 1"));
  EXPECT_THAT(testing::inputErrorOf([&] {
                makeField({{0, 0, 0}, {1, 0, 0}}, {0, 0}, {inf, 1.0f});
              }),
              HasSubstr("non-finite value (inf) at cell 0"));
}

TEST(AmrField, RejectsChannelSizeMismatchAndBadNames) {
  EXPECT_THAT(testing::inputErrorOf([] {
                makeField({{0, 0, 0}, {1, 0, 0}}, {0, 0}, {1.0f});
              }),
              HasSubstr("channel 'rho' has 1 values for 2 cells"));
  EXPECT_THAT(testing::inputErrorOf([] {
                AmrField({{0, 0, 0}}, {0}, {{"a", {1.0f}}, {"a", {2.0f}}}, {}, "x");
              }),
              HasSubstr("channel 'a' appears twice"));
  EXPECT_THAT(testing::inputErrorOf([] {
                AmrField({{0, 0, 0}}, {0}, {{"", {1.0f}}}, {}, "x");
              }),
              HasSubstr("empty name"));
}

TEST(AmrField, RejectsEmptyAndMismatchedCellArrays) {
  EXPECT_THAT(testing::inputErrorOf([] { makeField({}, {}); }), HasSubstr("no cells"));
  EXPECT_THAT(testing::inputErrorOf([] {
                AmrField({{0, 0, 0}}, {0, 0}, {}, {}, "x");
              }),
              HasSubstr("1 cell corners but 2 cell levels"));
}

TEST(AmrField, RejectsExtentBeyondSupportedRange) {
  EXPECT_THAT(testing::inputErrorOf([] {
                makeField({{0, 0, 0}, {1 << kMaxExtentBits, 0, 0}}, {0, 0});
              }),
              HasSubstr("per axis are supported"));
}

TEST(AmrField, RejectsCornersWhoseUpperFaceOverflowsInt) {
  const int top = std::numeric_limits<int>::max();
  EXPECT_THAT(testing::inputErrorOf([&] {
                makeField({{top, 0, 0}}, {0});
              }),
              HasSubstr("beyond the largest supported corner coordinate"));
  const int bottom = std::numeric_limits<int>::min();
  EXPECT_THAT(testing::inputErrorOf([&] {
                makeField({{bottom, 0, 0}, {top - 1, 0, 0}}, {0, 0});
              }),
              HasSubstr("per axis are supported"));
}

TEST(AmrField, RejectsTransformsThatFloat32PositionsCannotHold) {
  const auto withTransform = [](WorldTransform t) {
    return testing::inputErrorOf([&] {
      AmrField({{0, 0, 0}}, {0}, {{"rho", {1.0f}}}, t, "t.exa");
    });
  };
  EXPECT_THAT(withTransform({{1e308, 0, 0}, {1, 1, 1}}), HasSubstr("beyond the float32 range"));
  EXPECT_THAT(withTransform({{0, 0, 0}, {1e300, 1, 1}}), HasSubstr("finest cell width along x"));
  EXPECT_THAT(withTransform({{0, 0, 0}, {1, 1e-320, 1}}), HasSubstr("finest cell width along y"));
  EXPECT_THAT(withTransform({{0, 0, std::nan("")}, {1, 1, 1}}), HasSubstr("origin's z"));
  EXPECT_THAT(withTransform({{0, 0, 0}, {1, 1, -1}}), HasSubstr("t.exa: the finest cell width"));
  EXPECT_NO_THROW(
      AmrField({{0, 0, 0}}, {0}, {{"rho", {1.0f}}}, {{-1e30, 0, 0}, {1e-30, 1, 1}}, "ok.exa"));
}

TEST(AmrField, ChannelLookupListsAvailableChannels) {
  const AmrField field = makeField({{0, 0, 0}}, {0});
  EXPECT_EQ(&field.channel("rho"), &field.channels()[0]);
  EXPECT_FALSE(field.findChannel("velx").has_value());
  EXPECT_THAT(testing::inputErrorOf([&] { field.channel("velx"); }),
              HasSubstr("no channel named 'velx'; the channels are: rho"));
}

TEST(WorldTransform, RoundTripsBetweenCellUnitsAndPhysical) {
  WorldTransform t{{1.0, -2.0, 0.5}, {0.25, 0.5, 2.0}};
  const glm::dvec3 cell(3.0, 4.0, 5.0);
  EXPECT_EQ(t.toPhysical(cell), glm::dvec3(1.75, 0.0, 10.5));
  EXPECT_EQ(t.toCellUnits(t.toPhysical(cell)), cell);
}

}  // namespace
}  // namespace amrstream::bricks
