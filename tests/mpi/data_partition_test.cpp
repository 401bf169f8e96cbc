// partitionCells(): the boxes tile the domain and own every point once; without a halo the cut
// halves the cells; with one, no rank holds more cells (its box and the halo) than the median
// cut's larger side.

#include "mpi/data_partition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "random_amr.hpp"
#include "synth/generators.hpp"

namespace amrstream::mpi {
namespace {

std::int64_t volumeOf(glm::ivec3 lower, glm::ivec3 upper) {
  const glm::i64vec3 e = glm::i64vec3(upper) - glm::i64vec3(lower);
  return e.x * e.y * e.z;
}

// Cells whose centres lie within `halo` of the box.
std::size_t cellsHeld(const bricks::AmrField& f, glm::ivec3 lower, glm::ivec3 upper, double halo) {
  std::size_t held = 0;
  for (std::size_t i = 0; i < f.cellCount(); ++i) {
    const glm::dvec3 c = glm::dvec3(f.lowers()[i]) + 0.5 * std::ldexp(1.0, f.levels()[i]);
    held += glm::all(glm::greaterThanEqual(c, glm::dvec3(lower) - halo)) &&
            glm::all(glm::lessThan(c, glm::dvec3(upper) + halo));
  }
  return held;
}

// A cloud of about 200,000 cells in 4 levels.
bricks::AmrField smallCloud() {
  BuiltinOptions g;
  g.levels = 4;
  g.targetCells = 200'000;
  return synth::generate("cloud", g);
}

TEST(DataPartition, BoxesTileTheDomain) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    for (const int parts : {1, 2, 3, 5})
      for (const double halo : {0.0, 6.0}) {
        SCOPED_TRACE(::testing::Message()
                     << "seed " << seed << ", " << parts << " parts, halo " << halo);
        testing::RandomAmrOptions layout;
        layout.levels = 3;
        const bricks::AmrField f = testing::randomAmr(seed, layout);
        const DataPartition p = partitionCells(f, parts, halo);
        ASSERT_EQ(p.parts(), parts);
        std::int64_t volume = 0;
        for (int k = 0; k < parts; ++k) volume += volumeOf(p.lower[k], p.upper[k]);
        EXPECT_EQ(volume, volumeOf(f.bounds().lower, f.bounds().upper));
        for (std::size_t i = 0; i < f.cellCount(); i += 7) {
          const glm::dvec3 c = glm::dvec3(f.lowers()[i]) + 0.25;
          int owners = 0;
          for (int k = 0; k < parts; ++k)
            owners += glm::all(glm::greaterThanEqual(c, glm::dvec3(p.lower[k]))) &&
                      glm::all(glm::lessThan(c, glm::dvec3(p.upper[k])));
          EXPECT_EQ(owners, 1);
          const int k = p.ownerOf(c);
          EXPECT_TRUE(glm::all(glm::greaterThanEqual(c, glm::dvec3(p.lower[k]))) &&
                      glm::all(glm::lessThan(c, glm::dvec3(p.upper[k]))));
        }
      }
}

TEST(DataPartition, CutsAvoidDenseCellsWhenRanksHoldAHalo) {
  const bricks::AmrField f = smallCloud();
  const double halo = 20.0;
  const DataPartition median = partitionCells(f, 2, 0.0);
  const std::size_t left = cellsHeld(f, median.lower[0], median.upper[0], 0.0);
  EXPECT_NEAR(double(left), 0.5 * double(f.cellCount()), 0.01 * double(f.cellCount()));
  const DataPartition aware = partitionCells(f, 2, halo);
  const auto largest = [&](const DataPartition& p) {
    return std::max(cellsHeld(f, p.lower[0], p.upper[0], halo),
                    cellsHeld(f, p.lower[1], p.upper[1], halo));
  };
  EXPECT_LE(largest(aware), largest(median));
}

// With seeds, a side's load is the larger of its shares of cells (halo included) and of seeds:
// when every seed lies in one part of the cells-only cut, the cut moves so that this load is
// smaller than the cells-only cut's; without seeds the partition is the cells-only one.
TEST(DataPartition, SeedsWeighTheCutAsMuchAsCells) {
  const bricks::AmrField f = smallCloud();
  const double halo = 20.0;
  const DataPartition cellsOnly = partitionCells(f, 2, halo);
  const glm::dvec3 lower(cellsOnly.lower[0]), extent = glm::dvec3(cellsOnly.upper[0]) - lower;
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < 4000; ++i) {
    const double t = (double(i) + 0.5) / 4000.0;
    seeds.push_back(lower + extent * glm::dvec3(0.1 + 0.8 * t, 0.1 + 0.8 * (1.0 - t), 0.5));
  }
  const auto load = [&](const DataPartition& p) {
    double most = 0.0;
    for (int k = 0; k < 2; ++k) {
      std::size_t inside = 0;
      for (const glm::dvec3& s : seeds)
        inside += glm::all(glm::greaterThanEqual(s, glm::dvec3(p.lower[k]))) &&
                  glm::all(glm::lessThan(s, glm::dvec3(p.upper[k])));
      const double cells = double(cellsHeld(f, p.lower[k], p.upper[k], halo));
      most = std::max({most, cells / (0.5 * double(f.cellCount())),
                       double(inside) / (0.5 * double(seeds.size()))});
    }
    return most;
  };
  const DataPartition weighted = partitionCells(f, 2, halo, seeds);
  EXPECT_DOUBLE_EQ(load(cellsOnly), 2.0);  // every seed on one side
  EXPECT_LT(load(weighted), 1.9);
  const DataPartition none = partitionCells(f, 2, halo, {});
  EXPECT_EQ(none.lower, cellsOnly.lower);
  EXPECT_EQ(none.upper, cellsOnly.upper);
}

// Over a million cells the planes' counts are taken in parallel pieces: the cut of two parts
// is still the one a plain count of every centre's plane gives (the cost as partitionCells
// states it: the larger side's cells per part, each side with the cells within the halo).
TEST(DataPartition, ParallelPlaneCountsGiveTheSequentialCut) {
  BuiltinOptions g;
  g.levels = 4;
  g.targetCells = 1'500'000;
  const bricks::AmrField f = synth::generate("cloud", g);
  ASSERT_GT(f.cellCount(), std::size_t(1) << 20);
  const double halo = 20.0;
  const DataPartition p = partitionCells(f, 2, halo);
  const glm::ivec3 lower = f.bounds().lower, extent = f.bounds().upper - lower;
  const std::int64_t reach = std::int64_t(std::ceil(halo));
  const double total = double(f.cellCount());
  double bestCost = std::numeric_limits<double>::infinity();
  int bestAxis = -1, bestPlane = 0;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<std::int64_t> below(std::size_t(extent[axis]) + 1, 0);
    for (std::size_t i = 0; i < f.cellCount(); ++i) {
      const std::int64_t twice = 2 * std::int64_t(f.lowers()[i][axis]) + (1 << f.levels()[i]);
      ++below[std::size_t(std::clamp<std::int64_t>(twice / 2 - lower[axis], 0, extent[axis] - 1)) +
              1];
    }
    for (std::size_t i = 1; i < below.size(); ++i) below[i] += below[i - 1];
    for (int i = 1; i < extent[axis]; ++i) {
      const double left =
          double(below[std::size_t(std::min<std::int64_t>(i + reach, extent[axis]))]);
      const double right = total - double(below[std::size_t(std::max<std::int64_t>(i - reach, 0))]);
      const double cost = std::max(left, right);
      if (cost < bestCost) {
        bestCost = cost;
        bestAxis = axis;
        bestPlane = lower[axis] + i;
      }
    }
  }
  ASSERT_GE(bestAxis, 0);
  EXPECT_EQ(p.upper[0][bestAxis], bestPlane);
  EXPECT_EQ(p.lower[1][bestAxis], bestPlane);
}

}  // namespace
}  // namespace amrstream::mpi
