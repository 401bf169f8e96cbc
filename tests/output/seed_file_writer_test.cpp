// Writing seed files: the exact bytes, reading back the same doubles, and replacing the target.

#include "output/seed_file_writer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "input_error_of.hpp"

namespace amrstream::output {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

std::string contentsOf(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SeedFileWriter, WritesAHeaderAndOneLineOf17DigitsPerSeed) {
  flow::SeedList seeds;
  seeds.points = {{0.1, 0.2, 0.3}, {4, 5, 6}, {-1e-5, 1e300, 0}, {-0.0, 1.0 / 3.0, 0x1p-1074}};
  const fs::path path = fs::temp_directory_path() / "amrstream-seeds-bytes.txt";
  writeSeedFile(path, seeds);
  EXPECT_EQ(contentsOf(path),
            "# amrstream seeds: x y z in physical coordinates\n"
            "0.10000000000000001 0.20000000000000001 0.29999999999999999\n"
            "4 5 6\n"
            "-1.0000000000000001e-05 1.0000000000000001e+300 0\n"
            "-0 0.33333333333333331 4.9406564584124654e-324\n");
  fs::remove(path);
}

TEST(SeedFileWriter, WrittenSeedsReadBackExactly) {
  const flow::SeedList seeds = flow::randomSeedsInBox({-1e-4, 0.1, 3e5}, {2e-4, 0.7, 4e5}, 500, 9);
  const fs::path path = fs::temp_directory_path() / "amrstream-seeds-out.txt";
  writeSeedFile(path, seeds);
  EXPECT_EQ(flow::readSeedFile(path).points, seeds.points);
  EXPECT_THAT(testing::inputErrorOf([&] { writeSeedFile("/nonexistent/dir/s.txt", seeds); }),
              HasSubstr("/nonexistent/dir/s.txt: cannot create the seeds file (No such file"));
}

// The file is written beside the target and renamed over it: another name of the old file (a
// hard link) keeps the old contents, and no temporary is left.
TEST(SeedFileWriter, WritingReplacesTheFileInsteadOfWritingIntoIt) {
  const fs::path dir = fs::temp_directory_path() / "amrstream-seeds-replace";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "old.txt") << "1 2 3\n";
  fs::create_hard_link(dir / "old.txt", dir / "seeds.txt");
  flow::SeedList seeds;
  seeds.points = {{0.1, 0.2, 0.3}, {4, 5, 6}};
  writeSeedFile(dir / "seeds.txt", seeds);
  EXPECT_EQ(flow::readSeedFile(dir / "seeds.txt").points, seeds.points);
  EXPECT_EQ(flow::readSeedFile(dir / "old.txt").points,
            std::vector<glm::dvec3>{glm::dvec3(1, 2, 3)});
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"old.txt", "seeds.txt"}));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace amrstream::output
