#include "render/image/png_io.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "raw_png_writer.hpp"
#include "temp_dir_test.hpp"

namespace amrstream::render {
namespace {

using ::testing::HasSubstr;
using testing::RawPng;

class PngIoTest : public amrstream::testing::TempDirTest {};

Image randomImage(std::uint32_t width, std::uint32_t height, unsigned seed) {
  Image image(width, height);
  std::mt19937 random(seed);
  for (std::uint8_t& byte : image.rgba) byte = static_cast<std::uint8_t>(random());
  return image;
}

RawPng rawPng(std::uint32_t width, std::uint32_t height, int bitDepth, int colourType) {
  RawPng png;
  png.width = width;
  png.height = height;
  png.bitDepth = bitDepth;
  png.colourType = colourType;
  return png;
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

std::vector<char> fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::filesystem::path& path, const std::vector<char>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The 8-bit value libpng's png_set_scale_16 gives: the nearest to sample * 255 / 65535.
std::uint8_t scaledTo8(std::uint16_t sample) {
  return static_cast<std::uint8_t>(std::lround(sample * 255.0 / 65535.0));
}

TEST_F(PngIoTest, RoundTripKeepsEveryPixelAndAlpha) {
  const std::pair<std::uint32_t, std::uint32_t> sizes[] = {
      {1, 1}, {3, 5}, {5, 3}, {17, 2}, {64, 33}};
  unsigned seed = 1;
  for (const auto& [width, height] : sizes) {
    const Image written = randomImage(width, height, seed++);
    const auto path = dir_ / "round_trip.png";
    writePng(path, written);
    const Image read = readPng(path);
    EXPECT_EQ(read.width, width);
    EXPECT_EQ(read.height, height);
    EXPECT_EQ(read.rgba, written.rgba) << width << "x" << height;
  }
}

TEST_F(PngIoTest, WriteLeavesOnlyTheFinishedFile) {
  writePng(dir_ / "a.png", randomImage(4, 4, 7));
  writePng(dir_ / "a.png", randomImage(2, 3, 8));  // replaces the first
  std::vector<std::filesystem::path> entries;
  for (const auto& entry : std::filesystem::directory_iterator(dir_))
    entries.push_back(entry.path());
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].filename(), "a.png");
  EXPECT_EQ(readPng(dir_ / "a.png").rgba, randomImage(2, 3, 8).rgba);
}

// Written beside the target and renamed over it: another name of the old file (a hard link)
// keeps the old image.
TEST_F(PngIoTest, WritingReplacesTheFileInsteadOfWritingIntoIt) {
  writePng(dir_ / "old.png", randomImage(4, 4, 1));
  std::filesystem::create_hard_link(dir_ / "old.png", dir_ / "new.png");
  writePng(dir_ / "new.png", randomImage(3, 2, 2));
  EXPECT_EQ(readPng(dir_ / "new.png").rgba, randomImage(3, 2, 2).rgba);
  EXPECT_EQ(readPng(dir_ / "old.png").rgba, randomImage(4, 4, 1).rgba);
}

TEST_F(PngIoTest, WritingAnEmptyImageThrowsAndWritesNothing) {
  const auto path = dir_ / "empty.png";
  EXPECT_THAT(errorOf([&] { writePng(path, Image(0, 4)); }),
              AllOf(HasSubstr(path.string()), HasSubstr("empty")));
  EXPECT_THAT(errorOf([&] { writePng(path, Image()); }), HasSubstr("empty"));
  EXPECT_TRUE(std::filesystem::is_empty(dir_));
}

TEST_F(PngIoTest, WritingIntoAMissingDirectoryThrowsNamingThePath) {
  const auto path = dir_ / "missing" / "out.png";
  EXPECT_THAT(errorOf([&] { writePng(path, Image(2, 2)); }), HasSubstr(path.string()));
}

TEST_F(PngIoTest, WritingAnInconsistentImageThrows) {
  Image image(3, 3);
  image.rgba.pop_back();
  EXPECT_THAT(errorOf([&] { writePng(dir_ / "bad.png", image); }), HasSubstr("bad.png"));
}

TEST_F(PngIoTest, ReadingAMissingFileThrowsCannotOpen) {
  const auto path = dir_ / "absent.png";
  EXPECT_THAT(errorOf([&] { readPng(path); }),
              AllOf(HasSubstr(path.string()), HasSubstr("cannot open")));
}

TEST_F(PngIoTest, ReadingADirectoryThrowsNamingIt) {
  EXPECT_THAT(errorOf([&] { readPng(dir_); }), HasSubstr(dir_.string()));
}

TEST_F(PngIoTest, ReadingANonPngFileThrowsNotAPng) {
  const auto text = dir_ / "notes.png";
  std::ofstream(text) << "these are not the pixels you are looking for\n";
  EXPECT_THAT(errorOf([&] { readPng(text); }),
              AllOf(HasSubstr(text.string()), HasSubstr("not a PNG file")));
  const auto empty = dir_ / "empty.png";
  std::ofstream{empty};
  EXPECT_THAT(errorOf([&] { readPng(empty); }),
              AllOf(HasSubstr(empty.string()), HasSubstr("not a PNG file")));
}

TEST_F(PngIoTest, ReadingATruncatedFileThrows) {
  const auto whole = dir_ / "whole.png";
  writePng(whole, randomImage(40, 30, 3));
  const std::vector<char> bytes = fileBytes(whole);
  // Inside the signature, after it, in the header, in the pixel data, in the final chunk.
  for (const std::size_t keep : {std::size_t{4}, std::size_t{8}, std::size_t{20}, std::size_t{60},
                                 bytes.size() / 2, bytes.size() - 1}) {
    const auto cut = dir_ / "cut.png";
    writeBytes(cut, {bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(keep)});
    EXPECT_THAT(errorOf([&] { readPng(cut); }),
                AllOf(HasSubstr(cut.string()), HasSubstr("truncated or corrupt PNG")))
        << "keeping " << keep << " of " << bytes.size() << " bytes";
  }
}

TEST_F(PngIoTest, ReadingCorruptPixelDataThrowsWithTheLibpngReason) {
  const auto path = dir_ / "corrupt.png";
  writePng(path, randomImage(40, 30, 4));
  std::vector<char> bytes = fileBytes(path);
  bytes[bytes.size() / 2] ^= 0x5a;  // inside IDAT: its CRC no longer matches
  writeBytes(path, bytes);
  EXPECT_THAT(
      errorOf([&] { readPng(path); }),
      AllOf(HasSubstr(path.string()), HasSubstr("truncated or corrupt PNG: "), HasSubstr("IDAT")));
}

TEST_F(PngIoTest, ReadsEightBitGrayAsOpaqueRgba) {
  RawPng raw = rawPng(3, 2, 8, PNG_COLOR_TYPE_GRAY);
  raw.rows = {0, 128, 255, 7, 8, 9};
  writeRawPng(dir_ / "gray.png", raw);
  const Image image = readPng(dir_ / "gray.png");
  ASSERT_EQ(image.width, 3u);
  ASSERT_EQ(image.height, 2u);
  for (std::uint32_t y = 0; y < 2; ++y) {
    for (std::uint32_t x = 0; x < 3; ++x) {
      const std::uint8_t v = raw.rows[y * 3 + x];
      EXPECT_EQ(image.at(x, y), (Rgba8{v, v, v, 255})) << x << "," << y;
    }
  }
}

TEST_F(PngIoTest, ReadsSixteenBitGrayRoundedToEightBits) {
  const std::vector<std::uint16_t> samples = {0, 65535, 257 * 100, 1000, 40000, 32768};
  RawPng raw = rawPng(3, 2, 16, PNG_COLOR_TYPE_GRAY);
  for (const std::uint16_t s : samples) testing::appendSample16(raw.rows, s);
  writeRawPng(dir_ / "gray16.png", raw);
  const Image image = readPng(dir_ / "gray16.png");
  ASSERT_EQ(image.width * image.height, samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const std::uint8_t v = scaledTo8(samples[i]);
    EXPECT_EQ(image.at(i % 3, i / 3), (Rgba8{v, v, v, 255})) << samples[i];
  }
}

TEST_F(PngIoTest, ReadsSixteenBitRgbaAndGrayAlpha) {
  const std::uint16_t rgba[2][4] = {{65535, 0, 257 * 12, 257 * 200}, {1000, 40000, 65535, 0}};
  RawPng colour = rawPng(2, 1, 16, PNG_COLOR_TYPE_RGB_ALPHA);
  for (const auto& pixel : rgba) {
    for (const std::uint16_t s : pixel) testing::appendSample16(colour.rows, s);
  }
  writeRawPng(dir_ / "rgba16.png", colour);
  const Image image = readPng(dir_ / "rgba16.png");
  for (std::uint32_t x = 0; x < 2; ++x) {
    EXPECT_EQ(image.at(x, 0), (Rgba8{scaledTo8(rgba[x][0]), scaledTo8(rgba[x][1]),
                                     scaledTo8(rgba[x][2]), scaledTo8(rgba[x][3])}));
  }

  RawPng grayAlpha = rawPng(1, 2, 16, PNG_COLOR_TYPE_GRAY_ALPHA);
  for (const std::uint16_t s : {257 * 50, 257 * 60, 257 * 70, 257 * 80}) {
    testing::appendSample16(grayAlpha.rows, static_cast<std::uint16_t>(s));
  }
  writeRawPng(dir_ / "ga16.png", grayAlpha);
  const Image gray = readPng(dir_ / "ga16.png");
  EXPECT_EQ(gray.at(0, 0), (Rgba8{50, 50, 50, 60}));
  EXPECT_EQ(gray.at(0, 1), (Rgba8{70, 70, 70, 80}));
}

TEST_F(PngIoTest, ReadsPaletteWithTransparency) {
  RawPng raw = rawPng(4, 1, 8, PNG_COLOR_TYPE_PALETTE);
  raw.palette = {{10, 20, 30}, {200, 100, 50}, {1, 2, 3}};
  raw.transparentIndices = {0, 128};  // entry 2 has no tRNS value: opaque
  raw.rows = {0, 1, 2, 1};
  writeRawPng(dir_ / "palette.png", raw);
  const Image image = readPng(dir_ / "palette.png");
  EXPECT_EQ(image.at(0, 0), (Rgba8{10, 20, 30, 0}));
  EXPECT_EQ(image.at(1, 0), (Rgba8{200, 100, 50, 128}));
  EXPECT_EQ(image.at(2, 0), (Rgba8{1, 2, 3, 255}));
  EXPECT_EQ(image.at(3, 0), (Rgba8{200, 100, 50, 128}));
}

TEST_F(PngIoTest, ReadsOneBitGrayAndGrayWithATransparentValue) {
  RawPng bits = rawPng(10, 1, 1, PNG_COLOR_TYPE_GRAY);
  bits.rows = {0b1010'0000, 0b1100'0000};  // pixels 1 0 1 0 0 0 0 0 | 1 1
  writeRawPng(dir_ / "bits.png", bits);
  const Image image = readPng(dir_ / "bits.png");
  const int expected[10] = {1, 0, 1, 0, 0, 0, 0, 0, 1, 1};
  for (std::uint32_t x = 0; x < 10; ++x) {
    const std::uint8_t v = expected[x] ? 255 : 0;
    EXPECT_EQ(image.at(x, 0), (Rgba8{v, v, v, 255})) << x;
  }

  const png_color_16 transparent{.index = 0, .red = 0, .green = 0, .blue = 0, .gray = 9};
  RawPng keyed = rawPng(3, 1, 8, PNG_COLOR_TYPE_GRAY);
  keyed.transparentColour = &transparent;
  keyed.rows = {8, 9, 10};
  writeRawPng(dir_ / "keyed.png", keyed);
  const Image gray = readPng(dir_ / "keyed.png");
  EXPECT_EQ(gray.at(0, 0), (Rgba8{8, 8, 8, 255}));
  EXPECT_EQ(gray.at(1, 0).a, 0);
  EXPECT_EQ(gray.at(2, 0), (Rgba8{10, 10, 10, 255}));
}

TEST_F(PngIoTest, ReadsInterlacedRgb) {
  RawPng raw = rawPng(7, 5, 8, PNG_COLOR_TYPE_RGB);
  raw.interlaced = true;
  for (std::uint32_t y = 0; y < 5; ++y) {
    for (std::uint32_t x = 0; x < 7; ++x) {
      raw.rows.insert(raw.rows.end(),
                      {static_cast<std::uint8_t>(x * 30), static_cast<std::uint8_t>(y * 50),
                       static_cast<std::uint8_t>(x + y)});
    }
  }
  writeRawPng(dir_ / "interlaced.png", raw);
  const Image image = readPng(dir_ / "interlaced.png");
  for (std::uint32_t y = 0; y < 5; ++y) {
    for (std::uint32_t x = 0; x < 7; ++x) {
      EXPECT_EQ(image.at(x, y),
                (Rgba8{static_cast<std::uint8_t>(x * 30), static_cast<std::uint8_t>(y * 50),
                       static_cast<std::uint8_t>(x + y), 255}))
          << x << "," << y;
    }
  }
}

}  // namespace
}  // namespace amrstream::render
