#include "render/image/colour_bar.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "render/image/colour_bar_layout.hpp"

namespace amrstream::render {
namespace {

constexpr Rgba8 kBackground{90, 160, 200, 255};
constexpr Rgba8 kTickColour{240, 240, 240, 255};
constexpr ColourMap kAllMaps[] = {ColourMap::Viridis, ColourMap::Magma, ColourMap::CoolWarm};

bool contains(const PixelRect& outer, const PixelRect& inner) {
  return inner.x >= outer.x && inner.y >= outer.y &&
         inner.x + inner.width <= outer.x + outer.width &&
         inner.y + inner.height <= outer.y + outer.height;
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

// The background darkened by the panel: read where nothing else is drawn.
Rgba8 plainPanel(const Image& image, const ColourBarLayout& layout) {
  return image.at(static_cast<std::uint32_t>(layout.panel.x),
                  static_cast<std::uint32_t>(layout.panel.y));
}

struct Run {
  int first, width;
};

// Runs of tick-coloured pixels along row y between columns [x0, x1).
std::vector<Run> tickColouredRuns(const Image& image, int y, int x0, int x1) {
  std::vector<Run> runs;
  for (int x = x0; x < x1; ++x) {
    if (image.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)) != kTickColour)
      continue;
    if (!runs.empty() && runs.back().first + runs.back().width == x) {
      ++runs.back().width;
    } else {
      runs.push_back({x, 1});
    }
  }
  return runs;
}

// The columns between x0 and x1 that hold ink (pixels other than `plain`) in rows [y0, y1).
std::pair<int, int> inkedColumns(const Image& image, int x0, int x1, int y0, int y1, Rgba8 plain) {
  int first = x1, last = x0 - 1;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (image.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)) == plain) continue;
      first = std::min(first, x);
      last = std::max(last, x);
    }
  }
  return {first, last};
}

// Checks that the ticks drawn under the gradient lie at the expected columns: for each value,
// gradient.x + round(t * (width - 1)) with t from `coordinate` (the value or its log10) computed
// here, and that they carry these values' labels.
void expectTicksAt(std::uint32_t width, std::uint32_t height, const ColourBar& bar,
                   const std::vector<double>& values, double (*coordinate)(double),
                   const std::vector<std::string>& labels) {
  Image image(width, height, kBackground);
  drawColourBar(image, bar);
  const auto layout = layoutColourBar(width, height, bar);
  ASSERT_TRUE(layout.has_value());
  const PixelRect& g = layout->gradient;
  const int thickness = layout->labelPixelSize >= 24 ? 2 : 1;
  const double low = coordinate(bar.scale.min), high = coordinate(bar.scale.max);
  std::vector<Run> expected;
  for (const double v : values) {
    const double t = (coordinate(v) - low) / (high - low);
    const int x = g.x + static_cast<int>(std::lround(t * (g.width - 1)));
    expected.push_back({std::min(x, g.x + g.width - thickness), thickness});
  }
  // The row just below the gradient's frame holds only the marks.
  const std::vector<Run> found = tickColouredRuns(image, g.y + g.height + 1, g.x, g.x + g.width);
  ASSERT_EQ(found.size(), expected.size()) << width << "x" << height;
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_EQ(found[i].first, expected[i].first) << "tick " << values[i];
    EXPECT_EQ(found[i].width, expected[i].width) << "tick " << values[i];
  }
  ASSERT_EQ(layout->ticks.size(), labels.size());
  const Rgba8 panel = plainPanel(image, *layout);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const PlacedTick& tick = layout->ticks[i];
    EXPECT_EQ(tick.label.text, labels[i]);
    if (tick.label.text.empty()) continue;
    const PixelRect& box = tick.label.box;
    EXPECT_LE(std::abs(box.x + box.width / 2 - tick.x), 1) << labels[i];  // centred
    EXPECT_GT(pixelsDifferingFrom(image, box, panel), 5u) << labels[i];
  }
}

double identity(double v) { return v; }
double log10Of(double v) { return std::log10(v); }

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

TEST(ColourBarTest, TitleIsTheLabelWithItsUnitInBrackets) {
  EXPECT_EQ(colourBarTitle({ColourMap::Viridis, {}, "temperature", "K"}), "temperature [K]");
  EXPECT_EQ(colourBarTitle({ColourMap::Viridis, {}, "speed", ""}), "speed");
  EXPECT_EQ(colourBarTitle({ColourMap::Viridis, {}, "", "km/s"}), "[km/s]");
  EXPECT_EQ(colourBarTitle({ColourMap::Viridis, {}, "", ""}), "");
}

TEST(ColourBarTest, GradientCentreRowReproducesTheColourMapTable) {
  const std::pair<std::uint32_t, std::uint32_t> sizes[] = {
      {128, 128}, {300, 200}, {511, 300}, {512, 512}, {1024, 768}, {1920, 1080}, {2000, 128}};
  for (const ColourMap map : kAllMaps) {
    for (const auto& [width, height] : sizes) {
      const ColourBar bar{map, {ScaleKind::Linear, -2.5, 40.0}, "speed", "m/s"};
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

// A bar with its own colours (the volume's transfer function), stacked above the first: its
// gradient runs linearly from the first colour to the last, and the panels do not overlap.
TEST(ColourBarTest, ABarOfGivenColoursStacksAboveTheFirst) {
  const glm::vec3 low(0.2f, 0.3f, 0.55f), high(1.0f, 0.88f, 0.7f);
  const ColourBar first{ColourMap::Viridis, {ScaleKind::Linear, 0.0, 1.0}, "speed", ""};
  ColourBar volume{
      ColourMap::Viridis, {ScaleKind::Log, 1.0, 1e4}, "dens (volume)", "", {low, high}, 1};
  Image image(800, 600, kBackground);
  drawColourBar(image, volume);
  const auto below = layoutColourBar(800, 600, first), above = layoutColourBar(800, 600, volume);
  ASSERT_TRUE(below && above);
  EXPECT_LE(above->panel.y + above->panel.height, below->panel.y) << "the panels overlap";
  const PixelRect& g = above->gradient;
  const auto row = static_cast<std::uint32_t>(g.y + g.height / 2);
  for (int i = 0; i < g.width; ++i) {
    const float t = float(i) / float(g.width - 1);
    ASSERT_EQ(image.at(static_cast<std::uint32_t>(g.x + i), row), toRgba8(low + t * (high - low)))
        << "column " << i;
  }
  volume.stack = 40;  // no room that high: no bar
  EXPECT_FALSE(layoutColourBar(800, 600, volume).has_value());
}

// On a white figure the light bar keeps its panel light and its text dark; the dark bar the
// reverse.
TEST(ColourBarTest, ALightBarForLightBackgrounds) {
  for (const bool light : {true, false}) {
    ColourBar bar{ColourMap::Viridis, {ScaleKind::Linear, 0.0, 1.0}, "speed", "m/s"};
    bar.light = light;
    Image image(800, 600, {255, 255, 255, 255});
    drawColourBar(image, bar);
    const auto layout = layoutColourBar(800, 600, bar);
    ASSERT_TRUE(layout);
    const PixelRect& box = layout->title.box;
    int darkest = 255, lightest = 0;
    for (int y = box.y; y < box.y + box.height; ++y)
      for (int x = box.x; x < box.x + box.width; ++x) {
        const Rgba8 c = image.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
        darkest = std::min<int>(darkest, c.g), lightest = std::max<int>(lightest, c.g);
      }
    const Rgba8 panel = image.at(static_cast<std::uint32_t>(layout->panel.x + 1),
                                 static_cast<std::uint32_t>(layout->panel.y + 1));
    if (light) {
      EXPECT_GT(panel.g, 200) << "the light panel is dark";
      EXPECT_LT(darkest, 80) << "no dark text";
    } else {
      EXPECT_LT(panel.g, 140) << "the dark panel is light";
      EXPECT_GT(lightest, 200) << "no light text";
    }
  }
}

TEST(ColourBarTest, LinearTicksSitAtTheirValuesColumns) {
  const ColourBar bar{ColourMap::Viridis, {ScaleKind::Linear, -2.5, 40.0}, "speed", "m/s"};
  expectTicksAt(800, 600, bar, {0, 10, 20, 30, 40}, identity, {"0", "10", "20", "30", "40"});
  const ColourBar unit{ColourMap::Magma, {ScaleKind::Linear, 0.0, 1.0}, "u", ""};
  expectTicksAt(1920, 1080, unit, {0, 0.2, 0.4, 0.6, 0.8, 1.0}, identity,
                {"0", "0.2", "0.4", "0.6", "0.8", "1"});
}

TEST(ColourBarTest, LogTicksSitAtTheirDecadesColumns) {
  const ColourBar bar{ColourMap::Viridis, {ScaleKind::Log, 0.01, 1000.0}, "density", "g/cm^3"};
  const std::vector<double> decades = {0.01, 0.1, 1, 10, 100, 1000};
  const std::vector<std::string> labels = {"0.01", "0.1", "1", "10", "100", "1000"};
  expectTicksAt(1600, 900, bar, decades, log10Of, labels);
  // Large enough for 2-pixel marks.
  const ColourBar wide{ColourMap::Magma, {ScaleKind::Log, 0.003, 700.0}, "density", ""};
  expectTicksAt(3840, 2160, wide, {0.01, 0.1, 1, 10, 100}, log10Of,
                {"0.01", "0.1", "1", "10", "100"});
}

TEST(ColourBarTest, TitleIsDrawnAboveTheGradientAndTheUnitWidensIt) {
  const ColourBar plain{ColourMap::Viridis, {ScaleKind::Linear, 0, 1}, "temp", ""};
  ColourBar withUnit = plain;
  withUnit.unit = "K";
  std::pair<int, int> extents[2];
  for (int i = 0; i < 2; ++i) {
    const ColourBar& bar = i == 0 ? plain : withUnit;
    Image image(800, 600, kBackground);
    drawColourBar(image, bar);
    const auto layout = layoutColourBar(800, 600, bar);
    ASSERT_TRUE(layout.has_value());
    EXPECT_EQ(layout->title.text, i == 0 ? "temp" : "temp [K]");
    const PixelRect& p = layout->panel;
    const PixelRect& g = layout->gradient;
    const Rgba8 panel = plainPanel(image, *layout);
    // Between the panel's top and the gradient's frame.
    extents[i] = inkedColumns(image, p.x, p.x + p.width, p.y, g.y - 1, panel);
    EXPECT_LT(extents[i].first, extents[i].second);
    EXPECT_GT(pixelsDifferingFrom(image, {p.x, p.y, p.width, g.y - 1 - p.y}, panel), 30u);
    // The p of "temp" goes below the title's baseline.
    const auto below =
        inkedColumns(image, p.x, p.x + p.width, layout->title.baseline + 1, g.y - 1, panel);
    EXPECT_LE(below.first, below.second);
    EXPECT_LT(layout->title.box.y + layout->title.box.height, g.y - 1);
  }
  EXPECT_GT(extents[1].second - extents[1].first, extents[0].second - extents[0].first + 5);
}

TEST(ColourBarTest, TextIsDrawnOnThePanelAndNothingOutsideIt) {
  const ColourBar bar{ColourMap::Magma, {ScaleKind::Linear, 0.0, 1500.0}, "vorticity", "1/s"};
  Image image(400, 300, kBackground);
  drawColourBar(image, bar);
  const auto layout = layoutColourBar(400, 300, bar);
  ASSERT_TRUE(layout.has_value());
  EXPECT_EQ(layout->title.text, "vorticity [1/s]");
  const Rgba8 panel = plainPanel(image, *layout);
  EXPECT_LT(panel.r + panel.g + panel.b, kBackground.r + kBackground.g + kBackground.b);
  EXPECT_TRUE(contains(layout->panel, layout->title.box));
  EXPECT_GT(pixelsDifferingFrom(image, layout->title.box, panel), 5u);
  ASSERT_GE(layout->ticks.size(), 2u);
  EXPECT_EQ(layout->ticks.front().label.text, "0");
  EXPECT_EQ(layout->ticks.back().label.text, "1500");
  for (const PlacedTick& tick : layout->ticks) {
    EXPECT_TRUE(contains(layout->panel, tick.label.box)) << tick.value;
    EXPECT_GT(tick.label.box.y, layout->gradient.y + layout->gradient.height) << tick.value;
  }

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

TEST(ColourBarTest, TextSizeFollowsTheImagesShorterSide) {
  const ColourBar bar{ColourMap::Viridis, {ScaleKind::Linear, 0, 1}, "u", ""};
  EXPECT_EQ(layoutColourBar(800, 600, bar)->labelPixelSize, 11);  // 1.6 %: 9.6
  EXPECT_EQ(layoutColourBar(1920, 1080, bar)->labelPixelSize, 17);
  EXPECT_EQ(layoutColourBar(3840, 2160, bar)->labelPixelSize, 35);
  EXPECT_EQ(layoutColourBar(5000, 4000, bar)->labelPixelSize, 48);
  EXPECT_EQ(layoutColourBar(300, 2000, bar)->labelPixelSize, 11);
  for (const auto& [width, height] : {std::pair{800u, 600u}, {1920u, 1080u}, {5000u, 4000u}}) {
    const auto layout = layoutColourBar(width, height, bar);
    EXPECT_GT(layout->titlePixelSize, layout->labelPixelSize);
  }
}

TEST(ColourBarTest, EveryPartStaysInsideTheImageForAnySizeScaleAndText) {
  const std::string longLabel(300, 'M');
  const double nan = std::nan("");
  const ColourBar bars[] = {
      {ColourMap::Viridis, {ScaleKind::Linear, 0, 1}, "", ""},
      {ColourMap::CoolWarm, {ScaleKind::Linear, -1.23e-5, 4.56e-5}, "velocity magnitude", "km/s"},
      {ColourMap::Magma, {ScaleKind::Log, 1e-3, 1e9}, longLabel, "g cm^-3"},
      {ColourMap::Viridis, {ScaleKind::SymLog, -1e5, 1e5, 1.0}, "B_x", "\u00b5G"},
      {ColourMap::Magma, {ScaleKind::Linear, -1.23e+100, -4.56e+200}, "min above max", ""},
      {ColourMap::Magma, {ScaleKind::Linear, 5, 5}, "constant", ""},
      {ColourMap::Magma, {ScaleKind::Linear, nan, nan}, "nothing", ""},
      {ColourMap::Magma, {ScaleKind::Log, -1, 10}, "log through 0", ""},
  };
  std::size_t leftOut = 0, shownInside = 0;
  for (const ColourBar& bar : bars) {
    for (std::uint32_t width = 128; width <= 2200; width += width < 300 ? 7 : 211) {
      for (const std::uint32_t height : {128u, 131u, 200u, 777u}) {
        const std::string where =
            std::to_string(width) + "x" + std::to_string(height) + " " + bar.label.substr(0, 20);
        const auto layout = layoutColourBar(width, height, bar);
        ASSERT_TRUE(layout.has_value()) << where;
        const PixelRect imageRect{0, 0, static_cast<int>(width), static_cast<int>(height)};
        ASSERT_TRUE(contains(imageRect, layout->panel)) << where;
        const PixelRect& g = layout->gradient;
        const PixelRect framed{g.x - 1, g.y - 1, g.width + 2, g.height + 2};
        ASSERT_TRUE(contains(layout->panel, framed)) << where;
        if (!layout->title.text.empty()) {
          ASSERT_TRUE(contains(layout->panel, layout->title.box)) << where;
        }
        ASSERT_FALSE(layout->ticks.empty()) << where;
        ASSERT_FALSE(layout->ticks.front().label.text.empty()) << where;
        const PlacedText* previous = nullptr;
        for (std::size_t i = 0; i < layout->ticks.size(); ++i) {
          const PlacedTick& tick = layout->ticks[i];
          ASSERT_TRUE(tick.x >= g.x && tick.x < g.x + g.width) << where;
          ASSERT_TRUE(tick.x >= tick.mark.x && tick.x < tick.mark.x + tick.mark.width) << where;
          ASSERT_TRUE(contains(layout->panel, tick.mark)) << where;
          if (tick.label.text.empty()) {
            ++leftOut;
            continue;
          }
          shownInside += i > 0 && i + 1 < layout->ticks.size();
          ASSERT_TRUE(contains(layout->panel, tick.label.box)) << where << " " << tick.label.text;
          if (previous != nullptr) {  // shown labels do not touch
            ASSERT_LT(previous->box.x + previous->box.width, tick.label.box.x) << where;
          }
          previous = &tick.label;
        }
        // Image::set and blend throw on any pixel outside the image.
        Image image(width, height, kBackground);
        ASSERT_NO_THROW(drawColourBar(image, bar)) << where;
      }
    }
  }
  EXPECT_GT(leftOut, 0u);      // the sweep has crowded labels ...
  EXPECT_GT(shownInside, 0u);  // ... and room for some between the ends
}

TEST(ColourBarTest, ScalesWithoutTicksLabelTheirEnds) {
  const auto ends =
      layoutColourBar(400, 300, {ColourMap::Magma, {ScaleKind::Linear, 3, -2}, "", ""});
  ASSERT_EQ(ends->ticks.size(), 2u);
  EXPECT_EQ(ends->ticks[0].label.text, "3");
  EXPECT_EQ(ends->ticks[0].x, ends->gradient.x);
  EXPECT_EQ(ends->ticks[1].label.text, "-2");
  EXPECT_EQ(ends->ticks[1].x, ends->gradient.x + ends->gradient.width - 1);
  const auto one = layoutColourBar(400, 300, {ColourMap::Magma, {ScaleKind::Linear, 7, 7}, "", ""});
  ASSERT_EQ(one->ticks.size(), 1u);
  EXPECT_EQ(one->ticks[0].label.text, "7");
}

TEST(ColourBarTest, LongTitlesAreShortenedToThePanel) {
  const ColourBar bar{
      ColourMap::Viridis, {ScaleKind::Linear, 0, 1}, std::string(100, 'x') + " tail", "m"};
  const auto layout = layoutColourBar(200, 200, bar);
  ASSERT_TRUE(layout.has_value());
  const std::string& title = layout->title.text;
  EXPECT_EQ(title.substr(title.size() - 3), "\u2026");
  EXPECT_EQ(title.substr(0, 3), "xxx");
  EXPECT_TRUE(contains(layout->panel, layout->title.box));
}

TEST(ColourBarTest, NoLabelOrUnitLeavesOutTheTitleRow) {
  const auto withTitle =
      layoutColourBar(300, 300, {ColourMap::Viridis, {ScaleKind::Linear, 0, 1}, "T", ""});
  const auto unitOnly =
      layoutColourBar(300, 300, {ColourMap::Viridis, {ScaleKind::Linear, 0, 1}, "", "K"});
  const auto without =
      layoutColourBar(300, 300, {ColourMap::Viridis, {ScaleKind::Linear, 0, 1}, "", ""});
  EXPECT_TRUE(without->title.text.empty());
  EXPECT_EQ(unitOnly->title.text, "[K]");
  EXPECT_LT(without->panel.height, withTitle->panel.height);
  EXPECT_EQ(unitOnly->panel.height, withTitle->panel.height);
}

TEST(ColourBarTest, ImagesBelow128PixelsGetNothing) {
  const ColourBar bar{ColourMap::Viridis, {ScaleKind::Linear, 0, 1}, "label", "unit"};
  for (const auto& [width, height] :
       {std::pair{100u, 100u}, {127u, 500u}, {500u, 127u}, {0u, 0u}, {1u, 1u}}) {
    EXPECT_FALSE(layoutColourBar(width, height, bar).has_value());
    Image image(width, height, kBackground);
    const Image before = image;
    drawColourBar(image, bar);
    EXPECT_EQ(image.rgba, before.rgba) << width << "x" << height;
  }
  Image smallest(128, 128, kBackground);
  drawColourBar(smallest, bar);
  EXPECT_NE(smallest.rgba, Image(128, 128, kBackground).rgba);
}

}  // namespace
}  // namespace amrstream::render
