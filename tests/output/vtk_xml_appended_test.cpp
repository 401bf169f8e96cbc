#include "output/vtk_xml_appended.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "every_compression.hpp"
#include "output/vtk_xml_file.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::testing {
namespace {

namespace fs = std::filesystem;
using output::AppendedArray;
using output::AppendedFileWriter;
using output::BufferedWriter;
using output::Compression;

class AppendedFile : public TempDirTest, public ::testing::WithParamInterface<Compression> {
 protected:
  // A PolyData whose one point array "Bytes" (UInt8) holds `values`, written `chunk` bytes per
  // call; the piece claims as many points as there are bytes.
  fs::path write(const std::vector<std::uint8_t>& values, std::size_t chunk = 1) {
    const AppendedArray array{"Bytes", "UInt8", 1, values.size(), [&](BufferedWriter& out) {
                                for (std::size_t at = 0; at < values.size(); at += chunk) {
                                  out.write(std::as_bytes(std::span(values).subspan(
                                      at, std::min(chunk, values.size() - at))));
                                }
                              }};
    // A second array after it, so its offset depends on the first one's compressed size.
    const std::vector<std::int64_t> after{-1, 2, -3};
    const AppendedArray second{"After", "Int64", 1, after.size() * 8, [&](BufferedWriter& out) {
                                 for (const std::int64_t v : after) out.put(v);
                               }};
    AppendedFileWriter file("PolyData", GetParam());
    file.markup("  <PolyData>\n    <Piece NumberOfPoints=\"" + std::to_string(values.size()) +
                "\">\n      <PointData>\n");
    file.dataArray(array, 8);
    file.dataArray(second, 8);
    file.markup("      </PointData>\n    </Piece>\n  </PolyData>\n");
    const fs::path path = dir_ / "file.vtp";
    file.write(path);
    return path;
  }

  std::vector<std::uint8_t> readBack(const fs::path& path, std::size_t count) {
    const output::VtkXmlFile file(path);
    const output::XmlElement& pointData =
        *file.root().child("PolyData")->child("Piece")->child("PointData");
    EXPECT_EQ(file.integers(*pointData.dataArray("After"), 3, 1, "After"),
              (std::vector<std::int64_t>{-1, 2, -3}));
    const std::vector<std::int64_t> read =
        file.integers(*pointData.dataArray("Bytes"), count, 1, "Bytes");
    return {read.begin(), read.end()};
  }

  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename());
    return names;
  }
};

std::string fileText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_P(AppendedFile, RoundTripsRandomAndStructuredArraysOfEverySize) {
  const std::size_t block = output::kBlockBytes;
  for (const std::size_t size :
       {std::size_t(0), std::size_t(1), block, block + 1, 70 * block + 5}) {
    for (const bool random : {true, false}) {
      SCOPED_TRACE(::testing::Message() << size << " bytes, " << (random ? "random" : "ramp"));
      std::mt19937 generator(size);
      std::vector<std::uint8_t> values(size);
      for (std::size_t i = 0; i < size; ++i) {
        values[i] = random ? std::uint8_t(generator()) : std::uint8_t(i / 1000);
      }
      EXPECT_EQ(readBack(write(values, 777), size), values);
    }
  }
}

// As VTK writes them: the value, its closing quote, then spaces up to a fixed width.
TEST_P(AppendedFile, PadsEachOffsetToAFixedWidth) {
  const std::string text = fileText(write(std::vector<std::uint8_t>(100000, 7)));
  const std::regex offset(R"re(offset="(\d+)"( *)/>)re");
  std::vector<std::uint64_t> offsets;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), offset);
       it != std::sregex_iterator(); ++it) {
    EXPECT_EQ((*it)[1].length() + (*it)[2].length(), 20) << (*it)[0];
    offsets.push_back(std::stoull((*it)[1]));
  }
  ASSERT_EQ(offsets.size(), 2u);
  EXPECT_EQ(offsets[0], 0u);
  // Uncompressed: a UInt64 count and 100000 bytes; compressed, less.
  if (GetParam() == Compression::None) {
    EXPECT_EQ(offsets[1], 8u + 100000u);
  } else {
    EXPECT_LT(offsets[1], 100000u);
  }
}

TEST_P(AppendedFile, DeclaresTheCompressorOnlyWhenCompressed) {
  const std::string text = fileText(write({1, 2, 3}));
  const std::string header = text.substr(0, text.find('\n', text.find("<VTKFile")));
  const std::string compressor(output::vtkCompressorName(GetParam()));
  if (compressor.empty()) {
    EXPECT_THAT(header, ::testing::Not(::testing::HasSubstr("compressor")));
  } else {
    EXPECT_THAT(header, ::testing::HasSubstr("compressor=\"" + compressor + "\""));
  }
}

TEST_P(AppendedFile, AProducerThatWritesOtherThanItDeclaredLeavesNoFile) {
  for (const std::size_t written : {std::size_t(99), std::size_t(101), std::size_t(40000)}) {
    SCOPED_TRACE(written);
    const std::vector<std::uint8_t> values(written, 1);
    const AppendedArray wrong{"Wrong", "UInt8", 1, 100, [&](BufferedWriter& out) {
                                out.write(std::as_bytes(std::span(values)));
                              }};
    AppendedFileWriter file("PolyData", GetParam());
    file.dataArray(wrong, 4);
    try {
      file.write(dir_ / "file.vtp");
      FAIL() << "no exception";
    } catch (const std::logic_error& error) {
      EXPECT_THAT(error.what(), ::testing::HasSubstr("'Wrong' declared 100 bytes but wrote " +
                                                     std::to_string(written)));
    }
    EXPECT_TRUE(entries().empty());
  }
}

INSTANTIATE_TEST_SUITE_P(EveryCompression, AppendedFile, kEveryCompression, compressionTestName);

}  // namespace
}  // namespace amrstream::testing
