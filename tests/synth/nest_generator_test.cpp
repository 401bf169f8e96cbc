// generateNest(): cells per level, exact tiling, cubes nested about the centre, the spiral's
// values, option errors, and builtin:nest through generate().

#include "synth/nest_generator.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "input_error_of.hpp"
#include "synth/generators.hpp"
#include "synth/spiral_field.hpp"

namespace amrstream::synth {
namespace {

using ::testing::HasSubstr;

NestOptions nest(int levels, int rootCells = 6, int blockCells = 8) {
  NestOptions o;
  o.levels = levels;
  o.rootCells = rootCells;
  o.blockCells = blockCells;
  return o;
}

std::int64_t finestCellsPerAxis(const NestOptions& o) {
  return std::int64_t(o.rootCells) << (o.levels - 1);
}

glm::dvec3 centreInCells(const NestOptions& o) { return o.centre * double(finestCellsPerAxis(o)); }

std::int64_t cube(std::int64_t n) { return n * n * n; }
// Volumes of deep nests: a domain of 2^30 finest cells per axis holds 2^90.
using Volume = unsigned __int128;
Volume cubed(std::int64_t n) { return Volume(n) * Volume(n) * Volume(n); }

// Levels numbered 0 = finest, as the AmrField numbers them.
std::vector<std::size_t> expectedCellsPerLevel(const NestOptions& o) {
  if (o.levels == 1) return {std::size_t(cube(o.rootCells))};
  const std::int64_t hole = cube(o.blockCells / 2);
  std::vector<std::size_t> perLevel(o.levels, std::size_t(cube(o.blockCells) - hole));
  perLevel.front() = std::size_t(cube(o.blockCells));
  perLevel.back() = std::size_t(cube(o.rootCells) - hole);
  return perLevel;
}

// The cells of each level and the finer levels fill a cube (the AmrField constructor rejected
// overlaps), which holds the centre with at least one cell of that level on every side (an
// octree's cubes of 2 cells: inside).
void expectCubesAboutTheCentre(const bricks::AmrField& f, const NestOptions& o) {
  const glm::dvec3 centre = centreInCells(o);
  for (int level = 0; level < o.levels; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    glm::i64vec3 lower(std::numeric_limits<std::int64_t>::max()), upper(-1);
    Volume volume = 0;
    for (std::size_t i = 0; i < f.cellCount(); ++i) {
      if (f.levels()[i] > level) continue;
      const std::int64_t width = std::int64_t(1) << f.levels()[i];
      lower = glm::min(lower, glm::i64vec3(f.lowers()[i]));
      upper = glm::max(upper, glm::i64vec3(f.lowers()[i]) + width);
      volume += cubed(width);
    }
    const glm::i64vec3 extent = upper - lower;
    EXPECT_EQ(extent.x, extent.y);
    EXPECT_EQ(extent.x, extent.z);
    EXPECT_TRUE(volume == cubed(extent.x)) << "the cells leave holes in their box";
    const double margin = o.blockCells == 2 ? 0.0 : std::ldexp(1.0, level);
    if (level == o.levels - 1) continue;  // the whole domain
    EXPECT_EQ(extent.x, std::int64_t(o.blockCells) << level);
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(centre - glm::dvec3(lower), glm::dvec3(margin))));
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(glm::dvec3(upper) - centre, glm::dvec3(margin))));
    if (margin == 0.0) {
      EXPECT_TRUE(glm::all(glm::lessThan(centre, glm::dvec3(upper))));
    }
  }
}

TEST(NestGenerator, CellsPerLevelTileTheUnitDomain) {
  for (const NestOptions& o :
       {nest(1), nest(2), nest(6), nest(18), nest(9, 11, 10), nest(30, 2, 2), nest(12, 3, 2)}) {
    SCOPED_TRACE("levels " + std::to_string(o.levels));
    const bricks::AmrField f = synth::generateNest(o);
    EXPECT_EQ(f.source(), "builtin:nest");
    EXPECT_EQ(f.cellsPerLevel(), expectedCellsPerLevel(o));
    EXPECT_EQ(synth::nestCellCount(o), double(f.cellCount()));
    const std::int64_t extent = finestCellsPerAxis(o);
    Volume volume = 0;
    for (std::uint8_t level : f.levels()) volume += cubed(std::int64_t(1) << level);
    EXPECT_TRUE(volume == cubed(extent));
    EXPECT_EQ(f.bounds().lower, glm::ivec3(0));
    EXPECT_EQ(f.bounds().upper, glm::ivec3(int(extent)));
    EXPECT_EQ(f.transform().origin, glm::dvec3(0.0));
    EXPECT_EQ(f.transform().spacing, glm::dvec3(1.0 / double(extent)));
    EXPECT_EQ(f.info().format, "builtin");
    EXPECT_EQ(f.info().fileLevel(0), o.levels - 1);
  }
}

TEST(NestGenerator, EveryLevelsCubeSurroundsTheCentre) {
  for (const NestOptions& o :
       {nest(6), nest(18), nest(9, 11, 10), nest(5, 8, 12), nest(30, 2, 2), nest(12, 3, 2)}) {
    SCOPED_TRACE("levels " + std::to_string(o.levels));
    expectCubesAboutTheCentre(synth::generateNest(o), o);
  }
}

// Wherever the centre lies, the nest either is built, with its cubes about the centre, or is
// refused as not nesting: never a layout the AmrField rejects.
TEST(NestGenerator, CubesNestOrAreRefusedForAnyCentre) {
  std::size_t built = 0, refused = 0;
  for (const int blockCells : {4, 6, 8, 10})
    for (double x = 0.0; x <= 1.0; x += 0.0625)
      for (const double y : {0.41, 0.5, 0.58}) {
        NestOptions o = nest(7, blockCells / 2 + 5, blockCells);
        o.centre = {x, y, 0.47};
        SCOPED_TRACE(::testing::Message() << "blockCells " << blockCells << " centre " << x);
        const std::string error = testing::inputErrorOf([&] {
          expectCubesAboutTheCentre(synth::generateNest(o), o);
          ++built;
        });
        if (error == "no error") continue;
        EXPECT_THAT(error, HasSubstr("the nest cannot be centred on option centre"));
        ++refused;
      }
  EXPECT_GT(built, 0u);
  EXPECT_GT(refused, 0u);
}

// v = omega e_z x (x - c) + alpha (x - c) at every cell centre, from physical coordinates.
TEST(NestGenerator, VelocityIsTheSpiralAtCellCentres) {
  for (const NestOptions& o : {nest(6), nest(18)}) {
    SCOPED_TRACE("levels " + std::to_string(o.levels));
    const bricks::AmrField f = synth::generateNest(o);
    const std::array<const Channel*, 3> v{&f.channel("velx"), &f.channel("vely"),
                                          &f.channel("velz")};
    double worst = 0.0;
    for (std::size_t i = 0; i < f.cellCount(); ++i) {
      const double width = std::ldexp(1.0, f.levels()[i]);
      const glm::dvec3 d =
          f.transform().toPhysical(glm::dvec3(f.lowers()[i]) + 0.5 * width) - o.centre;
      const glm::dvec3 expected =
          glm::cross(glm::dvec3(0, 0, o.rotationRate), d) + o.expansionRate * d;
      const glm::dvec3 stored(v[0]->values[i], v[1]->values[i], v[2]->values[i]);
      worst = std::max(worst, glm::length(stored - expected) / glm::length(expected));
    }
    EXPECT_LT(worst, 1e-6);  // float storage
  }
}

TEST(NestGenerator, TracesOfTheSpiralTurnAboutTheCentreAndMoveOut) {
  const SpiralField spiral{2.0, 0.5};
  const glm::dvec3 d(1.0, 0.0, 0.5);
  const glm::dvec3 quarterTurn = spiral.offsetAfter(d, 0.25 * std::numbers::pi);
  const double growth = std::exp(0.125 * std::numbers::pi);
  EXPECT_NEAR(quarterTurn.x, 0.0, 1e-15);
  EXPECT_NEAR(quarterTurn.y, growth, 1e-15);
  EXPECT_NEAR(quarterTurn.z, 0.5 * growth, 1e-15);
  // The closed form solves dd/dt = v(d).
  const double dt = 1e-6;
  const glm::dvec3 rate = (spiral.offsetAfter(d, dt) - spiral.offsetAfter(d, -dt)) / (2.0 * dt);
  EXPECT_LT(glm::length(rate - spiral.velocity(d)), 1e-9);
}

TEST(NestGenerator, BadOptionsNameTheOption) {
  const auto rejects = [](NestOptions o, const std::string& words) {
    const std::string error = testing::inputErrorOf([&] { synth::generateNest(o); });
    EXPECT_THAT(error, HasSubstr("builtin:nest"));
    EXPECT_THAT(error, HasSubstr(words));
  };
  rejects(nest(0), "option levels is 0; it must be between 1 and 30");
  rejects(nest(31), "option levels is 31; it must be between 1 and 30");
  rejects(nest(6, 6, 7), "option blockCells is 7; it must be even and at least 2");
  rejects(nest(6, 6, 0), "option blockCells is 0; it must be even and at least 2");
  rejects(nest(6, 1, 2),
          "option rootCells is 1; with 6 levels and blockCells 2 it must be at least 2");
  rejects(nest(6, 5, 8),
          "option rootCells is 5; with 6 levels and blockCells 8 it must be at "
          "least 6");
  rejects(nest(1, 0, 8), "option rootCells is 0");
  rejects(nest(1, 1291, 8),
          "options rootCells 1291 and blockCells 8 make 2151685171 cells; at "
          "most 2147483647 are supported");
  rejects(nest(30, 6, 8), "option rootCells is 6; with 30 levels the domain would span 3221225472");
  NestOptions o = nest(6);
  o.centre = {0.3, 0.55, 0.47};
  rejects(o,
          "the nest cannot be centred on option centre (0.3, 0.55, 0.47): the cube of level 4 "
          "(0 = finest)");
  o.centre = {0.5, 1.5, 0.5};
  rejects(o, "option centre is (0.5, 1.5, 0.5); it must lie in the unit domain");
  o.centre = {0.5, std::numeric_limits<double>::quiet_NaN(), 0.5};
  rejects(o, "option centre is (0.5, nan, 0.5)");
  o = nest(6);
  o.expansionRate = std::numeric_limits<double>::infinity();
  rejects(o, "option expansionRate is inf; it must be finite");
  o = nest(6);
  o.maxSpeed = 0.0;
  rejects(o, "option maxSpeed is 0; it must be positive");
  o.maxSpeed = std::numeric_limits<double>::quiet_NaN();
  rejects(o, "option maxSpeed is nan; it must be positive");
}

// maxSpeed scales the faster cells' vectors down to it and leaves the slower ones as they were.
TEST(NestGenerator, MaxSpeedCapsTheSpiral) {
  NestOptions o = nest(8);
  const bricks::AmrField free = synth::generateNest(o);
  o.maxSpeed = 0.05;
  const bricks::AmrField capped = synth::generateNest(o);
  std::size_t scaled = 0, kept = 0;
  for (std::size_t i = 0; i < free.cellCount(); ++i) {
    glm::dvec3 a, b;
    for (int c = 0; c < 3; ++c) {
      const std::string name = std::string("vel") + "xyz"[c];
      a[c] = free.channel(name).values[i];
      b[c] = capped.channel(name).values[i];
    }
    if (glm::length(a) <= o.maxSpeed) {
      EXPECT_EQ(a, b);
      ++kept;
      continue;
    }
    EXPECT_NEAR(glm::length(b), o.maxSpeed, 1e-7);
    EXPECT_NEAR(glm::dot(a, b) / (glm::length(a) * glm::length(b)), 1.0, 1e-7);
    ++scaled;
  }
  EXPECT_GT(scaled, 0u);
  EXPECT_GT(kept, 0u);
}

TEST(NestGenerator, BuiltinNestIsTheDefaultNestWithTheGeneratorsLevelsAndTime) {
  BuiltinOptions g;
  g.levels = 7;
  g.time = 0.5;
  const bricks::AmrField builtin = generate("nest", g);
  NestOptions o = nest(7);
  o.time = 0.5;
  const bricks::AmrField direct = synth::generateNest(o);
  EXPECT_TRUE(std::ranges::equal(builtin.lowers(), direct.lowers()));
  EXPECT_TRUE(std::ranges::equal(builtin.levels(), direct.levels()));
  EXPECT_EQ(builtin.channel("velx").values, direct.channel("velx").values);
  EXPECT_EQ(builtin.info().time, 0.5);
  g.levels = 0;
  EXPECT_THAT(testing::inputErrorOf([&] { generate("nest", g); }), HasSubstr("option levels is 0"));
}

}  // namespace
}  // namespace amrstream::synth
