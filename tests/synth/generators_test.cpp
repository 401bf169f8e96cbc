// generate(): kinds, option errors, determinism, budgets, level use and exact tiling.

#include "synth/generators.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "amrstream/error.hpp"

namespace amrstream::synth {
namespace {

constexpr std::size_t kSplitCost = 7 * 512;

BuiltinOptions small(std::uint64_t seed = 1) {
  BuiltinOptions o;
  o.levels = 4;
  o.rootBlocks = 2;
  o.targetCells = 60'000;
  o.seed = seed;
  return o;
}

// The kinds that refine blocks within BuiltinOptions' budget; nest takes only the levels
// (nest_generator_test.cpp).
std::vector<std::string> blockKinds() {
  std::vector<std::string> kinds = generatorKinds();
  std::erase(kinds, "nest");
  return kinds;
}

void expectIdentical(const bricks::AmrField& a, const bricks::AmrField& b) {
  ASSERT_EQ(a.cellCount(), b.cellCount());
  EXPECT_TRUE(std::equal(a.lowers().begin(), a.lowers().end(), b.lowers().begin()));
  EXPECT_TRUE(std::equal(a.levels().begin(), a.levels().end(), b.levels().begin()));
  ASSERT_EQ(a.channels().size(), b.channels().size());
  for (std::size_t c = 0; c < a.channels().size(); ++c) {
    EXPECT_EQ(a.channels()[c].name, b.channels()[c].name);
    EXPECT_EQ(a.channels()[c].values, b.channels()[c].values) << a.channels()[c].name;
  }
}

TEST(Generators, ListsTheKinds) {
  EXPECT_EQ(generatorKinds(),
            (std::vector<std::string>{"rotation", "abc", "cloud", "swirl", "nest"}));
}

TEST(Generators, UnknownKindNamesItAndListsTheKinds) {
  try {
    generate("vortex", small());
    FAIL() << "accepted an unknown kind";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.source(), "builtin:vortex");
    EXPECT_NE(message.find("'vortex'"), std::string::npos) << message;
    for (const std::string& kind : generatorKinds())
      EXPECT_NE(message.find(kind), std::string::npos) << message;
  }
}

TEST(Generators, BadOptionsNameTheOption) {
  for (const std::string& kind : blockKinds()) {
    const auto rejects = [&](BuiltinOptions o, const std::string& word) {
      try {
        generate(kind, o);
        ADD_FAILURE() << kind << " accepted a bad " << word;
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
        EXPECT_EQ(e.source(), "builtin:" + kind);
      }
    };
    BuiltinOptions o = small();
    o.levels = 0;
    rejects(o, "levels");
    o.levels = 9;
    rejects(o, "levels");
    o = small();
    o.rootBlocks = 0;
    rejects(o, "rootBlocks");
    o = small();
    o.targetCells = 1000;
    rejects(o, "targetCells");
  }
}

TEST(Generators, SameOptionsGiveTheSameField) {
  for (const std::string& kind : generatorKinds()) {
    SCOPED_TRACE(kind);
    expectIdentical(generate(kind, small(7)), generate(kind, small(7)));
  }
}

TEST(Generators, AnotherSeedGivesAnotherCloud) {
  const bricks::AmrField a = generate("cloud", small(1));
  const bricks::AmrField b = generate("cloud", small(2));
  const bool sameLayout = a.cellCount() == b.cellCount() &&
                          std::equal(a.lowers().begin(), a.lowers().end(), b.lowers().begin()) &&
                          std::equal(a.levels().begin(), a.levels().end(), b.levels().begin());
  EXPECT_FALSE(sameLayout && a.channel("dens").values == b.channel("dens").values);
  EXPECT_NE(a.channel("magx").values, b.channel("magx").values);
}

TEST(Generators, KeepTheBudgetUseSeveralLevelsAndTileTheDomain) {
  for (const std::string& kind : blockKinds()) {
    for (const BuiltinOptions& o :
         {small(), BuiltinOptions{5, 1, 40'000, 3}, BuiltinOptions{3, 3, 100'000, 4}}) {
      SCOPED_TRACE(kind + " levels " + std::to_string(o.levels));
      const bricks::AmrField f = generate(kind, o);
      EXPECT_EQ(f.source(), "builtin:" + kind);
      EXPECT_LE(f.cellCount(), o.targetCells);
      EXPECT_GT(f.cellCount() + kSplitCost, o.targetCells) << "budget left unused";
      EXPECT_LE(f.coarsestLevel(), o.levels - 1);
      const std::vector<std::size_t> perLevel = f.cellsPerLevel();
      EXPECT_GT(
          std::count_if(perLevel.begin(), perLevel.end(), [](std::size_t n) { return n > 0; }), 1);

      // The AmrField constructor rejected overlaps; the volumes fill the domain exactly.
      const std::int64_t extent = std::int64_t(o.rootBlocks) * 8 << (o.levels - 1);
      std::int64_t volume = 0;
      for (std::uint8_t level : f.levels()) volume += std::int64_t(1) << (3 * level);
      EXPECT_EQ(volume, extent * extent * extent);
      EXPECT_EQ(f.bounds().lower, glm::ivec3(0));
      EXPECT_EQ(f.bounds().upper, glm::ivec3(int(extent)));
      EXPECT_EQ(f.transform().origin, glm::dvec3(0.0));
      EXPECT_DOUBLE_EQ(f.transform().spacing.x * double(extent), 1.0);
      EXPECT_EQ(f.transform().spacing.x, f.transform().spacing.z);
    }
  }
}

TEST(Generators, ChannelNames) {
  const auto names = [](const bricks::AmrField& f) {
    std::vector<std::string> out;
    for (const Channel& c : f.channels()) out.push_back(c.name);
    return out;
  };
  const std::vector<std::string> velocity{"velx", "vely", "velz"};
  EXPECT_EQ(names(generate("rotation", small())), velocity);
  EXPECT_EQ(names(generate("abc", small())), velocity);
  EXPECT_EQ(names(generate("cloud", small())),
            (std::vector<std::string>{"dens", "magx", "magy", "magz"}));
}

}  // namespace
}  // namespace amrstream::synth
