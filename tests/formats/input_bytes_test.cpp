// The reads every reader goes through: a file that delivers fewer bytes than its size promised
// (it shrank between the size check and the read) fails by name with the numbers involved, and
// paths that are not regular files or are too large are refused before anything is read.

#include "formats/input_bytes.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "input_error_of.hpp"
#include "special_files.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::formats {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

class InputBytes : public testing::TempDirTest {};

TEST_F(InputBytes, AFileShorterThanItsSizePromisedFailsByName) {
  const fs::path path = dir_ / "shrunk.cells";
  std::ofstream(path, std::ios::binary) << std::string(10, 'x');
  std::ifstream in;
  const std::uint64_t size = openRegularFile(in, path, "the cells file");
  EXPECT_EQ(size, 10u);
  // Reading on as if the file still had 24 bytes, as after a truncation by another process.
  std::string into(24, '\0');
  EXPECT_THAT(
      testing::inputErrorOf([&] { readExactly(in, path, 0, into.data(), 24, "the cells file"); }),
      HasSubstr(path.string() + ": the cells file: read 10 of 24 bytes from byte 0; the "
                                "file is shorter than it was a moment ago"));
}

TEST_F(InputBytes, WholeFilesAreReadExactly) {
  const fs::path path = dir_ / "Header";
  std::ofstream(path, std::ios::binary) << std::string("HyperCLaw\0two\n", 14);
  EXPECT_EQ(readWholeFile(path, "the Header"), std::string("HyperCLaw\0two\n", 14));
}

TEST_F(InputBytes, PathsThatAreNotSmallRegularFilesAreRefused) {
  EXPECT_THAT(testing::inputErrorOf([&] { readWholeFile(dir_, "the Header"); }),
              HasSubstr(dir_.string() + ": is a directory, not a file"));
  testing::makeFifo(dir_ / "fifo");
  EXPECT_THAT(
      testing::inputErrorWithoutHanging(dir_ / "fifo", [&] { readWholeFile(dir_ / "fifo", "x"); }),
      HasSubstr("is a FIFO"));
  const fs::path sparse = dir_ / "sparse";
  std::ofstream(sparse).close();
  fs::resize_file(sparse, std::uintmax_t{1} << 40);
  EXPECT_THAT(testing::inputErrorOf([&] { readWholeFile(sparse, "the parameter file"); }),
              HasSubstr(sparse.string() + ": the parameter file has 1099511627776 bytes, more "
                                          "than the 1073741824 accepted"));
}

TEST_F(InputBytes, LinesAreReadWholeUpToTheirBound) {
  const std::vector<std::size_t> lengths = {0, 1, 4095, 4096, 4097, 9000, 10000};
  std::string text;
  for (const std::size_t n : lengths) text += std::string(n, 'a' + char(n % 26)) + "\n";
  text += "last";  // no '\n' after the last line
  const fs::path path = dir_ / "lines.txt";
  std::ofstream(path, std::ios::binary) << text;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    ASSERT_TRUE(readBoundedLine(in, line, 10000, path.string(), long(i) + 1));
    EXPECT_EQ(line, std::string(lengths[i], 'a' + char(lengths[i] % 26))) << lengths[i];
  }
  ASSERT_TRUE(readBoundedLine(in, line, 10000, path.string(), 8));
  EXPECT_EQ(line, "last");
  EXPECT_FALSE(readBoundedLine(in, line, 10000, path.string(), 9));
  EXPECT_FALSE(readBoundedLine(in, line, 10000, path.string(), 9));

  std::ifstream again(path, std::ios::binary);
  for (long number = 1; number <= 6; ++number)  // the sixth has 9000 bytes: at the bound
    ASSERT_TRUE(readBoundedLine(again, line, 9000, path.string(), number));
  EXPECT_THAT(testing::inputErrorOf([&] { readBoundedLine(again, line, 9000, path.string(), 7); }),
              HasSubstr(path.string() + ":7: the line is longer than 9000 bytes"));
}

TEST_F(InputBytes, TextWithAHoleIsRefusedBeforeItIsRead) {
  const fs::path path = dir_ / "Header";
  if (!testing::makeSparseFile(path, "HyperCLaw-V1.1\n", std::uintmax_t(512) << 20))
    GTEST_SKIP() << "the file system of " << dir_ << " does not report holes (SEEK_HOLE)";
  EXPECT_THAT(testing::inputErrorOf([&] { readWholeFile(path, "the plotfile Header"); }),
              HasSubstr(path.string() + ": the plotfile Header has a hole from byte"));
}

}  // namespace
}  // namespace amrstream::formats
