// Seed files, random seed boxes, the domain check and the choice of vector channels.

#include "flow/seeds.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "flow/sampler.hpp"
#include "flow/vector_selection.hpp"
#include "flow_test_support.hpp"
#include "input_error_of.hpp"
#include "random_amr.hpp"

namespace amrstream::flow {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

fs::path writeSeeds(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / ("amrstream-seeds-" + name + ".txt");
  std::ofstream(path) << text;
  return path;
}

TEST(SeedFile, ReadsSpacesCommasTabsCommentsAndBlankLines) {
  const fs::path path = writeSeeds("good", "# seeds\n1 2 3\n\n4.5,5,6e-1 # trailing\n\t7\t8 9\r\n");
  const SeedList seeds = readSeedFile(path);
  ASSERT_EQ(seeds.points.size(), 3u);
  EXPECT_EQ(seeds.points[0], glm::dvec3(1, 2, 3));
  EXPECT_EQ(seeds.points[1], glm::dvec3(4.5, 5, 0.6));
  EXPECT_EQ(seeds.points[2], glm::dvec3(7, 8, 9));
  EXPECT_EQ(seeds.originOf(1), path.string() + ":4");
}

TEST(SeedFile, RejectsMalformedLinesNamingTheLine) {
  const fs::path path = writeSeeds("bad", "1 2 3\n1 2\n");
  EXPECT_THAT(testing::inputErrorOf([&] { readSeedFile(path); }),
              HasSubstr(path.string() + ":2: expected three numbers"));
  const fs::path extra = writeSeeds("extra", "1 2 3 4\n");
  EXPECT_THAT(testing::inputErrorOf([&] { readSeedFile(extra); }),
              HasSubstr(":1: unexpected text"));
  const fs::path nan = writeSeeds("nan", "1 nan 3\n");
  EXPECT_THAT(testing::inputErrorOf([&] { readSeedFile(nan); }),
              HasSubstr(":1: the seed has a non-finite"));
  const fs::path empty = writeSeeds("empty", "# nothing\n");
  EXPECT_THAT(testing::inputErrorOf([&] { readSeedFile(empty); }), HasSubstr("holds no seeds"));
  EXPECT_THAT(testing::inputErrorOf([&] { readSeedFile("/nonexistent/seeds.txt"); }),
              HasSubstr("/nonexistent/seeds.txt: no such file"));
}

// Checked before opening: a FIFO without a writer would block the reader, a device never end.
TEST(SeedFile, RefusesFifosDevicesAndDirectoriesByName) {
  const fs::path fifo =
      fs::temp_directory_path() / ("amrstream-seeds-fifo-" + std::to_string(::getpid()));
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THAT(testing::inputErrorOf([&] { readSeedFile(fifo); }),
              HasSubstr(fifo.string() + ": is a FIFO (named pipe), not a regular file"));
  fs::remove(fifo);
  EXPECT_THAT(testing::inputErrorOf([&] { readSeedFile("/dev/zero"); }),
              HasSubstr("/dev/zero: is a device, not a regular file"));
  EXPECT_THAT(testing::inputErrorOf([&] { readSeedFile(fs::temp_directory_path()); }),
              HasSubstr("is a directory"));
}

// A file whose size differs from what was read (here a /proc file, which says it is empty and is
// not) has changed underneath: refused by name, whatever its lines hold.
TEST(SeedFile, AFileThatChangesWhileItIsReadFailsByName) {
  EXPECT_THAT(testing::inputErrorOf([&] { readSeedFile("/proc/self/status"); }),
              HasSubstr("/proc/self/status: the file changed while it was read: 0 bytes when "
                        "opened, more read"));
}

TEST(SeedBox, IsReproducibleAndInsideTheBox) {
  const SeedList a = randomSeedsInBox({1, 2, 3}, {2, 4, 6}, 1000, 7);
  const SeedList b = randomSeedsInBox({1, 2, 3}, {2, 4, 6}, 1000, 7);
  const SeedList c = randomSeedsInBox({1, 2, 3}, {2, 4, 6}, 1000, 8);
  EXPECT_EQ(a.points, b.points);
  EXPECT_NE(a.points, c.points);
  for (const glm::dvec3& p : a.points) {
    EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, glm::dvec3(1, 2, 3))));
    EXPECT_TRUE(glm::all(glm::lessThan(p, glm::dvec3(2, 4, 6))));
  }
}

TEST(SeedCheck, NamesTheFirstSeedOutsideTheDomain) {
  const VectorVolume volume =
      testing::volumeOf(testing::uniformGrid(8, [](auto) { return glm::vec3(1.0f); }));
  const fs::path path = writeSeeds("outside", "1 1 1\n7.9 0 0\n8 1 1\n-0.1 1 1\n");
  const SeedList seeds = readSeedFile(path);
  EXPECT_THAT(testing::inputErrorOf([&] { checkSeedsInDomain(volume, seeds); }),
              HasSubstr(path.string() + ":3: seed (8, 1, 1) is outside the domain [0, 8) x"));
  SeedList inside;
  inside.points = {{0, 0, 0}, {7.99, 7.99, 7.99}};
  inside.origin = [](std::size_t i) { return std::string(i == 0 ? "a" : "b"); };
  EXPECT_NO_THROW(checkSeedsInDomain(volume, inside));
}

// The check runs on all cores; the seed it names is still the first outside, of many.
TEST(SeedCheck, NamesTheFirstOfManySeedsOutside) {
  const VectorVolume volume =
      testing::volumeOf(testing::uniformGrid(8, [](auto) { return glm::vec3(1.0f); }));
  SeedList seeds = randomSeedsInBox(glm::dvec3(0.5), glm::dvec3(7.5), 200000, 3);
  seeds.points[150001] = {9, 1, 1};
  seeds.points[70001] = {-1, 1, 1};
  seeds.points[199999] = {1, 1, 20};
  EXPECT_THAT(testing::inputErrorOf([&] { checkSeedsInDomain(volume, seeds); }),
              HasSubstr("random seed #70001: seed (-1, 1, 1) is outside the domain"));
  seeds.points[70001] = {1, 1, 1};
  EXPECT_THAT(testing::inputErrorOf([&] { checkSeedsInDomain(volume, seeds); }),
              HasSubstr("random seed #150001: seed (9, 1, 1)"));
}

// Without holes, a seed in the box passes without being sampled; it passes exactly when its
// sample is valid, near the faces and on them too.
TEST(SeedCheck, ASeedOfAFieldWithoutHolesPassesExactlyWhenItsSampleIsValid) {
  const bricks::AmrField field = testing::randomAmr(7, {4, {3, 2, 2}, 0.45, {0, 8, -16}});
  const VectorVolume volume = testing::volumeOf(field);
  ASSERT_TRUE(volume.cellsFillDomain);
  const glm::dvec3 lower(volume.domain.lower), upper(volume.domain.upper);
  const std::vector<glm::dvec3> points = testing::pointsInAndAroundBox(lower, upper, 0.25, 3000, 7);
  for (const glm::dvec3& cellUnits : points) {
    SeedList one;
    one.points = {volume.transform.toPhysical(cellUnits)};
    one.origin = [](std::size_t) { return std::string("seed"); };
    const bool valid =
        sampleVector(volume, toCellPoint(volume.transform.toCellUnits(one.points[0]))).valid;
    bool passed = true;
    try {
      checkSeedsInDomain(volume, one);
    } catch (const InputError&) {
      passed = false;
    }
    ASSERT_EQ(passed, valid) << cellUnits.x << " " << cellUnits.y << " " << cellUnits.z;
  }
}

TEST(SeedCheck, RefusesASeedWhereNoTentReachesSoNoSampleIsNaN) {
  // x = 7.5 is the lower face of the second block's domain: in its region, but every tent
  // function of its cells is zero there, so the sample (and point data) would be undefined.
  const VectorVolume volume = testing::volumeOf(testing::twoBlocksWithAGap());
  SeedList seeds;
  seeds.points = {{2.0, 2.0, 2.0}, {7.5, 2.0, 2.0}};
  seeds.origin = [](std::size_t i) { return std::string(i == 0 ? "a" : "b"); };
  EXPECT_THAT(testing::inputErrorOf([&] { checkSeedsInDomain(volume, seeds); }),
              HasSubstr("b: seed (7.5, 2, 2) lies on the outer face of the data"));
}

TEST(VectorSelection, PrefersVelocityThenMagneticFieldAndNamesTheVector) {
  const auto field = [](std::vector<std::string> names) {
    std::vector<Channel> channels;
    for (auto& n : names) channels.push_back({n, {0.0f}});
    return bricks::AmrField({{0, 0, 0}}, {0}, channels, {}, "f");
  };
  const VectorChannels both =
      chooseVectorChannels(field({"dens", "magx", "magy", "magz", "velx", "vely", "velz"}), "");
  EXPECT_EQ(both.channels, (std::array<std::string, 3>{"velx", "vely", "velz"}));
  EXPECT_EQ(both.name, "vel");
  EXPECT_EQ(chooseVectorChannels(field({"dens", "magx", "magy", "magz"}), "").name, "mag");
  EXPECT_EQ(chooseVectorChannels(field({"x-velocity", "y-velocity", "z-velocity"}), "").name,
            "velocity");
  EXPECT_EQ(chooseVectorChannels(field({"U", "V", "W"}), "").name, "velocity");
  EXPECT_EQ(chooseVectorChannels(field({"a", "b", "c"}), "c,b,a").channels,
            (std::array<std::string, 3>{"c", "b", "a"}));
  EXPECT_THAT(testing::inputErrorOf([&] {
                chooseVectorChannels(field({"a", "b"}), "");
              }),
              HasSubstr("choose three with --vector a,b,c (channels: a, b)"));
  EXPECT_THAT(testing::inputErrorOf([&] {
                chooseVectorChannels(field({"a", "b", "c"}), "a,b,d");
              }),
              HasSubstr("no channel named 'd'"));
  for (const char* bad : {"a,b", "a,b,c,a", "a,b,c,"})
    EXPECT_THAT(testing::inputErrorOf([&] {
                  chooseVectorChannels(field({"a", "b", "c"}), bad);
                }),
                HasSubstr("exactly three channels"))
        << bad;
}

}  // namespace
}  // namespace amrstream::flow
