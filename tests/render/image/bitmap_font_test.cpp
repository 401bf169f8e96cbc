#include "render/image/bitmap_font.hpp"

#include <gtest/gtest.h>

#include <climits>
#include <set>
#include <stdexcept>
#include <string>

namespace amrstream::render {
namespace {

constexpr Rgba8 kPaper{20, 40, 60, 255};
constexpr Rgba8 kInk{250, 240, 230, 255};

std::size_t countInk(const Image& image) {
  std::size_t count = 0;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) count += image.at(x, y) == kInk;
  }
  return count;
}

Image drawn(std::uint32_t width, std::uint32_t height, int x, int y, std::string_view text,
            int scale = 1) {
  Image image(width, height, kPaper);
  drawText(image, x, y, text, kInk, scale);
  return image;
}

std::string printableAscii() {
  std::string all;
  for (char c = ' '; c <= '~'; ++c) all += c;
  return all;
}

TEST(BitmapFontTest, MeasuresFiveBySevenCellsWithOneColumnBetween) {
  EXPECT_EQ(textWidth("", 1), 0);
  EXPECT_EQ(textWidth("A", 1), 5);
  EXPECT_EQ(textWidth("AB", 1), 11);
  EXPECT_EQ(textWidth("0.25", 2), 46);
  EXPECT_EQ(textHeight(1), 7);
  EXPECT_EQ(textHeight(3), 21);
  EXPECT_THROW(textWidth("A", 0), std::invalid_argument);
  EXPECT_THROW(textHeight(-1), std::invalid_argument);
  Image image(8, 8);
  EXPECT_THROW(drawText(image, 0, 0, "A", kInk, 0), std::invalid_argument);
}

TEST(BitmapFontTest, EveryGlyphStaysInItsCellAndOnlySpaceIsBlank) {
  for (const char c : printableAscii()) {
    const Image image = drawn(25, 27, 10, 10, std::string(1, c));
    std::size_t inside = 0;
    for (std::uint32_t y = 0; y < image.height; ++y) {
      for (std::uint32_t x = 0; x < image.width; ++x) {
        if (image.at(x, y) == kPaper) continue;
        const bool inCell = x >= 10 && x < 15 && y >= 10 && y < 17;
        EXPECT_TRUE(inCell) << "'" << c << "' drew at " << x << "," << y;
        inside += inCell;
      }
    }
    EXPECT_EQ(inside == 0, c == ' ') << "'" << c << "'";
  }
}

// The 35 pixels of a 5x7 image, one bit each: set where ink is.
std::uint64_t inkBits(const Image& glyph) {
  std::uint64_t bits = 0;
  for (std::uint32_t y = 0; y < 7; ++y) {
    for (std::uint32_t x = 0; x < 5; ++x) bits = bits << 1 | (glyph.at(x, y) == kInk);
  }
  return bits;
}

TEST(BitmapFontTest, AllPrintableGlyphsDiffer) {
  std::set<std::uint64_t> seen;
  for (const char c : printableAscii()) {
    EXPECT_TRUE(seen.insert(inkBits(drawn(5, 7, 0, 0, std::string(1, c)))).second)
        << "'" << c << "' looks like an earlier glyph";
  }
}

TEST(BitmapFontTest, UnknownBytesDrawAsQuestionMark) {
  const Image question = drawn(5, 7, 0, 0, "?");
  for (const char c : {'\x01', '\n', '\x7f', '\xc3', '\xff'}) {
    EXPECT_EQ(drawn(5, 7, 0, 0, std::string(1, c)).rgba, question.rgba) << int(c);
  }
}

TEST(BitmapFontTest, EightHasMoreInkThanOne) {
  EXPECT_GT(countInk(drawn(5, 7, 0, 0, "8")), countInk(drawn(5, 7, 0, 0, "1")));
}

TEST(BitmapFontTest, CharactersAdvanceSixColumns) {
  Image separate(20, 9, kPaper);
  drawText(separate, 2, 1, "A", kInk);
  drawText(separate, 8, 1, "B", kInk);
  EXPECT_EQ(drawn(20, 9, 2, 1, "AB").rgba, separate.rgba);
}

TEST(BitmapFontTest, ScaleMagnifiesEachFontPixel) {
  const std::string text = "Ag5%";
  const Image small = drawn(24, 7, 0, 0, text, 1);
  const Image large = drawn(72, 21, 0, 0, text, 3);
  ASSERT_EQ(textWidth(text, 3), 3 * textWidth(text, 1));
  for (std::uint32_t y = 0; y < large.height; ++y) {
    for (std::uint32_t x = 0; x < large.width; ++x) {
      ASSERT_EQ(large.at(x, y), small.at(x / 3, y / 3)) << x << "," << y;
    }
  }
}

TEST(BitmapFontTest, DrawsOnlyInsideTheTextBox) {
  const std::string text = "Hello, 1.5e+03";
  const Image image = drawn(100, 20, 5, 4, text);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const bool inBox = x >= 5 && x < 5u + textWidth(text, 1) && y >= 4 && y < 11;
      if (!inBox) {
        ASSERT_EQ(image.at(x, y), kPaper) << x << "," << y;
      }
    }
  }
  EXPECT_GT(countInk(image), 50u);
}

// Oracle: the same text drawn into a canvas three times as large, offset so that the small
// canvas is its middle window; the window's pixels must match whatever clipping the edges need.
TEST(BitmapFontTest, ClipsAtEveryEdgeExactly) {
  const std::uint32_t width = 23, height = 11;
  const std::string text = "W8@|";
  for (const int scale : {1, 2}) {
    for (int y = -16; y <= 13; y += 3) {
      for (int x = -50; x <= 26; x += 5) {
        const Image clipped = drawn(width, height, x, y, text, scale);
        const Image whole = drawn(3 * width, 3 * height, x + static_cast<int>(width),
                                  y + static_cast<int>(height), text, scale);
        for (std::uint32_t py = 0; py < height; ++py) {
          for (std::uint32_t px = 0; px < width; ++px) {
            ASSERT_EQ(clipped.at(px, py), whole.at(px + width, py + height))
                << "text at " << x << "," << y << " scale " << scale << ", pixel " << px << ","
                << py;
          }
        }
      }
    }
  }
}

TEST(BitmapFontTest, FarAwayTextDrawsNothing) {
  const std::string text(1000, '#');
  for (const auto& [x, y] : {std::pair{INT_MIN, 0},
                             {INT_MAX, 0},
                             {0, INT_MIN},
                             {0, INT_MAX},
                             {-100000, 2},
                             {INT_MAX - 3, INT_MAX - 3},
                             {INT_MIN, INT_MIN}}) {
    for (const int scale : {1, 7, 1000}) {
      const Image image = drawn(16, 16, x, y, text, scale);
      EXPECT_EQ(countInk(image), 0u) << x << "," << y << " scale " << scale;
    }
  }
  // A huge glyph over the whole canvas clips to it.
  EXPECT_EQ(countInk(drawn(16, 16, -1000, -1000, "#", 1000)), 16u * 16u);
}

TEST(BitmapFontTest, TranslucentInkBlends) {
  Image image(5, 7, {0, 0, 0, 255});
  drawText(image, 0, 0, "8", {255, 255, 255, 128});
  EXPECT_EQ(image.at(1, 0), (Rgba8{128, 128, 128, 255}));  // the top bar of the 8
  EXPECT_EQ(image.at(0, 0), (Rgba8{0, 0, 0, 255}));
}

}  // namespace
}  // namespace amrstream::render
