#include "render/image/colour_bar.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "render/image/bitmap_font.hpp"
#include "render/image/colour_bar_layout.hpp"

namespace amrstream::render {
namespace {

constexpr Rgba8 kBackground{90, 160, 200, 255};
constexpr ColourMap kAllMaps[] = {ColourMap::Viridis, ColourMap::Magma, ColourMap::CoolWarm};

bool contains(const PixelRect& outer, const PixelRect& inner) {
  return inner.x >= outer.x && inner.y >= outer.y &&
         inner.x + inner.width <= outer.x + outer.width &&
         inner.y + inner.height <= outer.y + outer.height;
}

PixelRect boxOf(const PlacedText& text, int scale) {
  return {text.x, text.y, textWidth(text.text, scale), textHeight(scale)};
}

std::size_t pixelsDifferingFrom(const Image& image, const PixelRect& rect, Rgba8 colour) {
  std::size_t count = 0;
  for (int y = rect.y; y < rect.y + rect.height; ++y) {
    for (int x = rect.x; x < rect.x + rect.width; ++x) {
      count += image.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)) != colour;
    }
  }
  return count;
}

TEST(ColourBarTest, FormatsValuesWithThreeSignificantDigits) {
  EXPECT_EQ(formatBarValue(0.0), "0");
  EXPECT_EQ(formatBarValue(-0.0), "0");
  EXPECT_EQ(formatBarValue(0.25), "0.25");
  EXPECT_EQ(formatBarValue(1500.0), "1.5e+03");
  EXPECT_EQ(formatBarValue(-3.2e-05), "-3.2e-05");
  EXPECT_EQ(formatBarValue(1.0), "1");
  EXPECT_EQ(formatBarValue(100.0), "100");
  EXPECT_EQ(formatBarValue(1.0 / 3.0), "0.333");
  EXPECT_EQ(formatBarValue(123456.0), "1.23e+05");
  EXPECT_EQ(formatBarValue(0.001), "0.001");
  EXPECT_EQ(formatBarValue(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(formatBarValue(std::nan("")), "nan");
}

TEST(ColourBarTest, GradientCentreRowReproducesTheColourMapTable) {
  const std::pair<std::uint32_t, std::uint32_t> sizes[] = {
      {128, 128}, {300, 200}, {511, 300}, {512, 512}, {1024, 768}, {1920, 1080}, {2000, 128}};
  for (const ColourMap map : kAllMaps) {
    for (const auto& [width, height] : sizes) {
      const ColourBar bar{map, -2.5, 40.0, "speed"};
      Image image(width, height, kBackground);
      drawColourBar(image, bar);
      const auto layout = layoutColourBar(width, height, bar);
      ASSERT_TRUE(layout.has_value()) << width << "x" << height;
      const PixelRect& g = layout->gradient;
      EXPECT_GE(g.width, std::max(64, static_cast<int>(width) / 3));
      EXPECT_GT(g.x + g.width / 2, static_cast<int>(width) / 2);  // right half
      EXPECT_GT(g.y, static_cast<int>(height) / 2);               // bottom half
      const std::vector<glm::vec3> table = colourMapTable(map, static_cast<std::size_t>(g.width));
      const auto row = static_cast<std::uint32_t>(g.y + g.height / 2);
      for (int i = 0; i < g.width; ++i) {
        ASSERT_EQ(image.at(static_cast<std::uint32_t>(g.x + i), row), toRgba8(table[i]))
            << colourMapName(map) << " " << width << "x" << height << " column " << i;
      }
    }
  }
}

TEST(ColourBarTest, LabelAndValuesAreDrawnOnThePanelAndNothingOutsideIt) {
  const ColourBar bar{ColourMap::Magma, 0.0, 1500.0, "vorticity"};
  Image image(400, 300, kBackground);
  drawColourBar(image, bar);
  const auto layout = layoutColourBar(400, 300, bar);
  ASSERT_TRUE(layout.has_value());
  EXPECT_EQ(layout->label.text, "vorticity");
  EXPECT_EQ(layout->minValue.text, "0");
  EXPECT_EQ(layout->maxValue.text, "1.5e+03");

  // The panel's top-left pixel is plain panel: the background darkened.
  const Rgba8 panel = image.at(static_cast<std::uint32_t>(layout->panel.x),
                               static_cast<std::uint32_t>(layout->panel.y));
  EXPECT_LT(panel.r + panel.g + panel.b, kBackground.r + kBackground.g + kBackground.b);
  for (const PlacedText* text : {&layout->label, &layout->minValue, &layout->maxValue}) {
    const PixelRect box = boxOf(*text, layout->scale);
    EXPECT_TRUE(contains(layout->panel, box)) << text->text;
    EXPECT_GT(pixelsDifferingFrom(image, box, panel), 5u) << text->text;
  }
  // Under the left end and the right end of the gradient.
  EXPECT_EQ(layout->minValue.x, layout->gradient.x);
  EXPECT_EQ(boxOf(layout->maxValue, layout->scale).x + textWidth("1.5e+03", layout->scale),
            layout->gradient.x + layout->gradient.width);
  EXPECT_GT(layout->minValue.y, layout->gradient.y + layout->gradient.height);
  EXPECT_LT(layout->label.y + textHeight(layout->scale), layout->gradient.y);

  const PixelRect& p = layout->panel;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const bool inPanel = static_cast<int>(x) >= p.x && static_cast<int>(x) < p.x + p.width &&
                           static_cast<int>(y) >= p.y && static_cast<int>(y) < p.y + p.height;
      if (!inPanel) {
        ASSERT_EQ(image.at(x, y), kBackground) << x << "," << y;
      }
    }
  }
}

TEST(ColourBarTest, TextScaleFollowsTheImageWidth) {
  const ColourBar bar{ColourMap::Viridis, 0, 1, "u"};
  EXPECT_EQ(layoutColourBar(511, 600, bar)->scale, 1);
  EXPECT_EQ(layoutColourBar(512, 600, bar)->scale, 2);
  EXPECT_EQ(layoutColourBar(1535, 600, bar)->scale, 2);
  EXPECT_EQ(layoutColourBar(1536, 600, bar)->scale, 3);
  EXPECT_EQ(layoutColourBar(3840, 2160, bar)->scale, 3);
  // Too short for scale 3: a smaller one that fits.
  EXPECT_LT(layoutColourBar(2000, 128, bar)->scale, 3);
}

TEST(ColourBarTest, EveryPartStaysInsideTheImageForAnySizeAndText) {
  const std::string longLabel(300, 'M');
  const ColourBar bars[] = {
      {ColourMap::Viridis, 0, 1, ""},
      {ColourMap::CoolWarm, -1.23e-5, 4.56e-5, "velocity magnitude [km/s]"},
      {ColourMap::Magma, -1.23e+100, -4.56e+200, longLabel},
  };
  for (const ColourBar& bar : bars) {
    for (std::uint32_t width = 128; width <= 2200; width += width < 300 ? 7 : 211) {
      for (const std::uint32_t height : {128u, 131u, 200u, 777u}) {
        const auto layout = layoutColourBar(width, height, bar);
        ASSERT_TRUE(layout.has_value());
        const PixelRect imageRect{0, 0, static_cast<int>(width), static_cast<int>(height)};
        ASSERT_TRUE(contains(imageRect, layout->panel)) << width << "x" << height;
        const PixelRect framed{layout->gradient.x - 1, layout->gradient.y - 1,
                               layout->gradient.width + 2, layout->gradient.height + 2};
        ASSERT_TRUE(contains(layout->panel, framed)) << width << "x" << height;
        for (const PlacedText* text : {&layout->label, &layout->minValue, &layout->maxValue}) {
          if (text->text.empty()) continue;
          ASSERT_TRUE(contains(layout->panel, boxOf(*text, layout->scale)))
              << width << "x" << height << " '" << text->text << "'";
        }
        // Image::set and blend throw on any pixel outside the image.
        Image image(width, height, kBackground);
        ASSERT_NO_THROW(drawColourBar(image, bar));
      }
    }
  }
}

TEST(ColourBarTest, LongLabelsAreShortenedToTheGradientWidth) {
  const ColourBar bar{ColourMap::Viridis, 0, 1, std::string(100, 'x') + " tail"};
  const auto layout = layoutColourBar(200, 200, bar);
  ASSERT_TRUE(layout.has_value());
  EXPECT_EQ(layout->label.text.substr(layout->label.text.size() - 2), "..");
  EXPECT_EQ(layout->label.text.substr(0, 3), "xxx");
  EXPECT_LE(textWidth(layout->label.text, layout->scale), layout->gradient.width);
}

TEST(ColourBarTest, EmptyLabelLeavesOutTheLabelRow) {
  const auto withLabel = layoutColourBar(300, 300, {ColourMap::Viridis, 0, 1, "T"});
  const auto without = layoutColourBar(300, 300, {ColourMap::Viridis, 0, 1, ""});
  EXPECT_TRUE(without->label.text.empty());
  EXPECT_LT(without->panel.height, withLabel->panel.height);
}

TEST(ColourBarTest, ImagesBelow128PixelsGetNothing) {
  for (const auto& [width, height] :
       {std::pair{100u, 100u}, {127u, 500u}, {500u, 127u}, {0u, 0u}, {1u, 1u}}) {
    const ColourBar bar{ColourMap::Viridis, 0, 1, "label"};
    EXPECT_FALSE(layoutColourBar(width, height, bar).has_value());
    Image image(width, height, kBackground);
    const Image before = image;
    drawColourBar(image, bar);
    EXPECT_EQ(image.rgba, before.rgba) << width << "x" << height;
  }
  Image smallest(128, 128, kBackground);
  drawColourBar(smallest, {ColourMap::Viridis, 0, 1, "label"});
  EXPECT_NE(smallest.rgba, Image(128, 128, kBackground).rgba);
}

}  // namespace
}  // namespace amrstream::render
