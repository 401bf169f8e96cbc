#include "render/image/font.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>

namespace amrstream::render {
namespace {

constexpr Rgba8 kPaper{20, 40, 60, 255};
constexpr Rgba8 kInk{250, 240, 230, 255};
constexpr int kSize = 24;

Image drawn(std::uint32_t width, std::uint32_t height, int x, int baseline, std::string_view text) {
  Image image(width, height, kPaper);
  defaultFont().drawText(image, x, baseline, text, kInk, kSize);
  return image;
}

// The rows [first, last] holding any pixel that is not paper; nullopt for a blank image.
std::optional<std::pair<int, int>> inkedRows(const Image& image) {
  std::optional<std::pair<int, int>> rows;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      if (image.at(x, y) == kPaper) continue;
      const int row = static_cast<int>(y);
      rows = rows ? std::pair{rows->first, row} : std::pair{row, row};
      break;
    }
  }
  return rows;
}

// Sets an environment variable, or unsets it for nullopt, until it goes out of scope.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* before = std::getenv(name)) before_ = before;
    set(value);
  }
  ~ScopedVariable() { set(before_); }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;

 private:
  void set(const std::optional<std::string>& value) {
    if (value) {
      setenv(name_, value->c_str(), 1);
    } else {
      unsetenv(name_);
    }
  }
  const char* name_;
  std::optional<std::string> before_;
};

std::size_t inkedPixels(const Image& image) {
  std::size_t count = 0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) count += image.at(x, y) != kPaper;
  return count;
}

TEST(FontTextTest, DescendersReachBelowTheBaselineAndCapitalsDoNot) {
  constexpr int baseline = 40;
  const auto descenders = inkedRows(drawn(120, 64, 10, baseline, "gpq"));
  ASSERT_TRUE(descenders.has_value());
  EXPECT_GE(descenders->second, baseline + kSize / 6);  // DejaVu's descenders: about 0.23 em
  EXPECT_LT(descenders->first, baseline - kSize / 3);

  const auto capital = inkedRows(drawn(120, 64, 10, baseline, "T"));
  ASSERT_TRUE(capital.has_value());
  EXPECT_EQ(capital->second, baseline - 1);
  EXPECT_LE(capital->first, baseline - kSize * 2 / 3);  // cap height: about 0.73 em

  // "temp" reads "temp", not "temP": the p goes below the baseline.
  const auto temp = inkedRows(drawn(120, 64, 10, baseline, "temp"));
  ASSERT_TRUE(temp.has_value());
  EXPECT_GE(temp->second, baseline + kSize / 6);
}

TEST(FontTextTest, MetricsBoundTheInkOfALine) {
  const LineMetrics line = defaultFont().lineMetrics(kSize);
  EXPECT_GT(line.ascent, kSize * 2 / 3);
  EXPECT_GT(line.descent, kSize / 6);
  EXPECT_LE(line.height(), 2 * kSize);
  constexpr int baseline = 40;
  const auto rows = inkedRows(drawn(300, 80, 4, baseline, "Tgjpq|([{}])"));
  ASSERT_TRUE(rows.has_value());
  EXPECT_GE(rows->first, baseline - line.ascent);
  EXPECT_LT(rows->second, baseline + line.descent);
}

TEST(FontTextTest, WidthGrowsWithTheTextAndSize) {
  const Font& font = defaultFont();
  EXPECT_EQ(font.textWidth("", kSize), 0);
  const int t = font.textWidth("t", kSize), temp = font.textWidth("temp", kSize);
  EXPECT_GT(t, 0);
  EXPECT_GT(temp, t);
  EXPECT_GT(font.textWidth("temperature", kSize), temp);
  EXPECT_GT(font.textWidth("temp", 2 * kSize), temp);
  // The ink lies within the measured width, give or take a pixel of overhang.
  const Image image = drawn(200, 64, 20, 40, "temp");
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      if (image.at(x, y) == kPaper) continue;
      EXPECT_GE(static_cast<int>(x), 20 - 1);
      EXPECT_LE(static_cast<int>(x), 20 + temp);
    }
  }
}

TEST(FontTextTest, InkIsTheColourWhereCoverageIsFullAndBlendsAtTheEdges) {
  const Image image = drawn(60, 40, 10, 30, "H");
  std::size_t full = 0, partial = 0;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const Rgba8 c = image.at(x, y);
      full += c == kInk;
      partial += c != kInk && c != kPaper;
      EXPECT_EQ(c.a, 255);
    }
  }
  EXPECT_GT(full, 20u);
  EXPECT_GT(partial, 0u);  // anti-aliased
  // A translucent colour only goes part of the way.
  Image faint(60, 40, kPaper);
  defaultFont().drawText(faint, 10, 30, "H", {250, 240, 230, 100}, kSize);
  for (std::uint32_t y = 0; y < faint.height; ++y)
    for (std::uint32_t x = 0; x < faint.width; ++x) EXPECT_LT(faint.at(x, y).r, 200);
  EXPECT_GT(inkedPixels(faint), 20u);
}

TEST(FontTextTest, TextPartlyOutsideTheImageInksOnlyTheInsideLikeACrop) {
  // The same text on a large image, offset by (40, 40), holds the small image as a crop.
  const std::string text = "gpqT Wj";
  const std::pair<int, int> origins[] = {{-15, 10}, {20, 4}, {5, 50}, {-200, 20}, {10, -30}};
  for (const auto& [x, baseline] : origins) {
    const Image small = drawn(40, 24, x, baseline, text);
    const Image large = drawn(200, 120, x + 40, baseline + 40, text);
    for (std::uint32_t y = 0; y < small.height; ++y)
      for (std::uint32_t column = 0; column < small.width; ++column)
        ASSERT_EQ(small.at(column, y), large.at(column + 40, y + 40))
            << x << "," << baseline << " at " << column << "," << y;
  }
  EXPECT_GT(inkedPixels(drawn(40, 24, -15, 10, text)), 0u);
  // Far away, at the ends of int: nothing drawn, nothing thrown.
  for (const int far : {INT32_MIN, INT32_MAX}) {
    EXPECT_EQ(inkedPixels(drawn(40, 24, far, 10, text)), 0u);
    EXPECT_EQ(inkedPixels(drawn(40, 24, 0, far, text)), 0u);
  }
  EXPECT_EQ(inkedPixels(drawn(0, 0, 0, 0, text)), 0u);
}

TEST(FontTextTest, KerningAndUnknownCharactersAreSafe) {
  const Font& font = defaultFont();
  // Invalid UTF-8 and a character DejaVu Sans lacks draw a box each; no throw.
  Image image(200, 40, kPaper);
  EXPECT_NO_THROW(font.drawText(image, 2, 30, "a\xff\xc3z \U0001F600", kInk, kSize));
  EXPECT_GT(font.textWidth("\xff", kSize), 0);
  // Non-ASCII that the font has: a micro sign and a superscript three, as in units.
  EXPECT_GT(font.textWidth("\u00b5m g/cm\u00b3", kSize), font.textWidth("m g/cm", kSize));
}

TEST(FontTextTest, PixelSizesOutsideTheRangeAreRefused) {
  const Font& font = defaultFont();
  Image image(8, 8);
  EXPECT_THROW(font.textWidth("a", 0), std::invalid_argument);
  EXPECT_THROW(font.lineMetrics(kMaxFontPixelSize + 1), std::invalid_argument);
  EXPECT_THROW(font.drawText(image, 0, 4, "a", kInk, -3), std::invalid_argument);
}

TEST(FontTextTest, AMissingFontIsAnErrorNamingItsPathAndTheFix) {
  const std::filesystem::path path = [] {
    const ScopedVariable font("AMRSTREAM_FONT", "/nonexistent/font.ttf");
    return fontPath();
  }();
  EXPECT_EQ(path, "/nonexistent/font.ttf");
  try {
    const Font font(path);
    FAIL() << "loaded a font from " << path;
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("/nonexistent/font.ttf"), std::string::npos) << message;
    EXPECT_NE(message.find("fonts-dejavu-core"), std::string::npos) << message;
    EXPECT_NE(message.find("AMRSTREAM_FONT"), std::string::npos) << message;
  }
}

TEST(FontTextTest, AFileThatIsNoFontIsAnErrorNamingIt) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "amrstream_font_test_not_a_font.ttf";
  std::ofstream(path) << "this is not a TrueType font\n";
  try {
    const Font font(path);
    FAIL() << "loaded a font from " << path;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
  EXPECT_THROW(Font(std::filesystem::temp_directory_path()), std::runtime_error);  // a folder
}

TEST(FontTextTest, TheBuiltInPathIsUsedWithoutTheEnvironmentVariable) {
  const std::filesystem::path builtIn = [] {
    const ScopedVariable font("AMRSTREAM_FONT", std::nullopt);
    return fontPath();
  }();
  const std::filesystem::path whenEmpty = [] {
    const ScopedVariable font("AMRSTREAM_FONT", "");
    return fontPath();
  }();
  EXPECT_FALSE(builtIn.empty());
  EXPECT_EQ(whenEmpty, builtIn);
  EXPECT_NO_THROW(Font{builtIn});
}

}  // namespace
}  // namespace amrstream::render
