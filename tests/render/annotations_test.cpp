#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "glm_pixel.hpp"
#include "render/annotations/axes.hpp"
#include "render/annotations/line_drawing.hpp"
#include "render/annotations/overlay_text.hpp"
#include "render/annotations/scale_bar.hpp"
#include "render/annotations/triad.hpp"

namespace amrstream::render {
namespace {

constexpr Rgba8 kBackground{0, 0, 0, 255};
constexpr Rgba8 kInk{255, 255, 255, 255};

using testing::glmPixel;

bool isInk(const Image& image, glm::vec2 position) {
  const float x = std::floor(position.x), y = std::floor(position.y);
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return true;  // clipped: unseen
  return image.at(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)) != kBackground;
}

// Whether v is a multiple of 1, 2 or 5 times a power of ten.
bool isOneTwoFiveTimesPowerOfTen(double v) {
  const double mantissa = v / std::pow(10.0, std::floor(std::log10(v) + 1e-9));
  for (const double round : {1.0, 2.0, 5.0})
    if (std::abs(mantissa - round) < 1e-6) return true;
  return false;
}

bool isWholeMultiple(double value, double step) {
  const double k = value / step;
  return std::abs(k - std::round(k)) < 1e-6 * std::max(1.0, std::abs(k));
}

TEST(LineDrawing, AWideHorizontalLineCoversItsPixelsAndNoOthers) {
  Image image(40, 40, kBackground);
  drawLine(image, {10.0f, 20.5f}, {30.0f, 20.5f}, 3.0f, kInk);
  for (std::uint32_t y = 0; y < 40; ++y) {
    for (std::uint32_t x = 0; x < 40; ++x) {
      const bool inside = x >= 10 && x < 30 && y >= 19 && y <= 21;
      EXPECT_EQ(image.at(x, y), inside ? kInk : kBackground) << x << ", " << y;
    }
  }
}

TEST(LineDrawing, ADiagonalLineIsPartlyCoveredAtItsSidesAndClippedToTheImage) {
  Image image(50, 50, kBackground);
  drawLine(image, {-100.0f, -100.0f}, {1e4f, 1e4f}, 2.0f, kInk, LineCap::Round);
  EXPECT_EQ(image.at(25, 25), kInk);
  EXPECT_EQ(image.at(49, 49), kInk);
  const Rgba8 side = image.at(26, 25);  // its centre is 0.71 px from the line's centre
  EXPECT_GT(side.r, 0);
  EXPECT_LT(side.r, 255);
  EXPECT_EQ(image.at(28, 25), kBackground);
}

// The longest projection of an edge along `axis` of the box whose corners land at `corners`
// (corner i at the upper bound of axis a where bit a of i is set) that has every corner on one
// side of its line; -1 when none has.
float longestEdgeOnTheOutline(const std::vector<glm::vec2>& corners, int axis) {
  float longest = -1.0f;
  for (int start = 0; start < 8; ++start) {
    if (start >> axis & 1) continue;
    const glm::vec2 from = corners[start], along = corners[start | 1 << axis] - from;
    if (glm::length(along) < 1e-2f) continue;
    const glm::vec2 across = glm::normalize(glm::vec2(-along.y, along.x));
    float lowest = INFINITY, highest = -INFINITY;
    for (const glm::vec2& corner : corners) {
      const float side = glm::dot(corner - from, across);
      lowest = std::min(lowest, side), highest = std::max(highest, side);
    }
    if (lowest > -0.05f || highest < 0.05f) longest = std::max(longest, glm::length(along));
  }
  return longest;
}

struct RandomScene {
  OrbitCamera camera;
  std::uint32_t width, height;
  WorldTransform transform;
  glm::dvec3 lower, upper;  // physical
};

RandomScene randomScene(std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RandomScene s;
  s.transform.origin = glm::dvec3(unit(random), unit(random), unit(random)) * 200.0 - 100.0;
  s.transform.spacing = glm::dvec3(unit(random), unit(random), unit(random)) * 0.09 + 0.01;
  s.lower = s.transform.origin + glm::dvec3(unit(random), unit(random), unit(random)) * 3.0;
  s.upper = s.lower + glm::dvec3(unit(random), unit(random), unit(random)) * 20.0 + 0.5;
  OrbitCamera camera;
  camera.azimuthDegrees = static_cast<float>(360.0 * unit(random));
  camera.elevationDegrees = static_cast<float>(-80.0 + 160.0 * unit(random));
  camera.fovYDegrees = static_cast<float>(15.0 + 60.0 * unit(random));
  camera.up = {int(random() % 3), random() % 2 ? 1.0f : -1.0f};
  camera.projection = random() % 2 ? Projection::Perspective : Projection::Orthographic;
  s.width = 256 + random() % 1400;
  s.height = 256 + random() % 1000;
  const glm::vec3 lowerCell(s.transform.toCellUnits(s.lower));
  const glm::vec3 upperCell(s.transform.toCellUnits(s.upper));
  // Zoomed out so that the labels have room.
  s.camera = frameBox(camera, lowerCell, upperCell, float(s.width) / float(s.height), 0.7f);
  return s;
}

TEST(Axes, TicksSitOnTheOutermostEdgesAtRoundValuesWhereGlmProjectsThem) {
  std::mt19937 random(17);
  int axesWithTicks = 0;
  for (int scene = 0; scene < 200; ++scene) {
    const RandomScene s = randomScene(random);
    const float w = float(s.width), h = float(s.height);
    const int labelSize = overlayLabelPixelSize(s.width, s.height);
    const AxesLayout layout =
        layoutAxes(s.camera, s.width, s.height, s.lower, s.upper, s.transform, labelSize);
    Image image(s.width, s.height, kBackground);
    drawAxes(image, layout, kInk);

    std::vector<glm::vec2> corners;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::dvec3 p((corner & 1) ? s.upper.x : s.lower.x, (corner & 2) ? s.upper.y : s.lower.y,
                         (corner & 4) ? s.upper.z : s.lower.z);
      corners.push_back(glmPixel(s.camera, w, h, glm::vec3(s.transform.toCellUnits(p))));
    }
    std::vector<PixelRect> labels;
    for (const AxisLayout& axis : layout.axes) {
      const int a = axis.axis;
      // Where an edge along the axis is on the box's outline, the axis shows when it is long
      // enough (and takes an edge on the outline, below).
      const float outlineEdge = longestEdgeOnTheOutline(corners, a);
      if (outlineEdge >= 0.0f && outlineEdge < kMinAxisEdgePixels - 0.1f) {
        EXPECT_FALSE(axis.shown) << "scene " << scene << " axis " << a;
      }
      if (outlineEdge > kMinAxisEdgePixels + 0.1f) {
        EXPECT_TRUE(axis.shown) << "scene " << scene << " axis " << a;
      }
      if (!axis.shown) continue;
      const glm::dvec3 start = s.transform.toPhysical(axis.edgeStart);
      const glm::dvec3 end = s.transform.toPhysical(axis.edgeEnd);
      const double tolerance = 1e-4 * (s.upper[a] - s.lower[a]) + 1e-4;
      EXPECT_NEAR(start[a], s.lower[a], tolerance) << scene;
      EXPECT_NEAR(end[a], s.upper[a], tolerance) << scene;
      for (int other = 0; other < 3; ++other) {
        if (other == a) continue;
        const double t = 1e-4 * (s.upper[other] - s.lower[other]) + 1e-4;
        EXPECT_TRUE(std::abs(start[other] - s.lower[other]) < t ||
                    std::abs(start[other] - s.upper[other]) < t)
            << scene;
        EXPECT_NEAR(end[other], start[other], t) << scene;
      }
      const glm::vec2 pixelStart = glmPixel(s.camera, w, h, axis.edgeStart);
      EXPECT_NEAR(axis.pixelStart.x, pixelStart.x, 1e-3f * w) << scene;
      EXPECT_NEAR(axis.pixelStart.y, pixelStart.y, 1e-3f * h) << scene;
      const glm::vec2 pixelEnd = glmPixel(s.camera, w, h, axis.edgeEnd);
      EXPECT_NEAR(axis.pixelEnd.x, pixelEnd.x, 1e-3f * w) << scene;
      EXPECT_NEAR(axis.pixelEnd.y, pixelEnd.y, 1e-3f * h) << scene;
      // On the outline, where any edge along the axis is: every corner of the box lies on the
      // inner side of the edge's line.
      if (outlineEdge >= 0.0f) {
        for (const glm::vec2& corner : corners)
          EXPECT_LE(glm::dot(corner - pixelStart, axis.outward), 1e-3f * (w + h))
              << "scene " << scene << " axis " << a;
      }

      const double span = s.upper[a] - s.lower[a];
      const double decade = std::pow(10.0, std::floor(std::log10(span / 4.0)));
      axesWithTicks += !axis.ticks.empty();
      EXPECT_LE(axis.ticks.size(), 5u);
      for (std::size_t i = 0; i < axis.ticks.size(); ++i) {
        const AxisTick& tick = axis.ticks[i];
        const glm::vec2 expected = glmPixel(s.camera, w, h, tick.point);
        EXPECT_NEAR(tick.pixel.x, expected.x, 1e-3f * w) << scene;
        EXPECT_NEAR(tick.pixel.y, expected.y, 1e-3f * h) << scene;
        const glm::dvec3 physical = s.transform.toPhysical(tick.point);
        EXPECT_NEAR(physical[a], tick.value, tolerance) << scene;
        for (int other = 0; other < 3; ++other) {
          if (other != a) {
            EXPECT_NEAR(physical[other], start[other], 1e-4 * span + 1e-4);
          }
        }
        EXPECT_GE(tick.value, s.lower[a] - 1e-9) << scene;
        EXPECT_LE(tick.value, s.upper[a] + 1e-9) << scene;
        EXPECT_TRUE(isWholeMultiple(tick.value, decade)) << tick.value << " " << decade;
        if (i > 0) {
          const double step = axis.ticks[1].value - axis.ticks[0].value;
          EXPECT_TRUE(isOneTwoFiveTimesPowerOfTen(step)) << step;
          EXPECT_TRUE(isWholeMultiple(tick.value, step)) << tick.value << " " << step;
          EXPECT_NEAR(tick.value - axis.ticks[i - 1].value, step, 1e-9 * span);
        }
        EXPECT_TRUE(isInk(image, 0.5f * (tick.pixel + tick.markEnd)))
            << "scene " << scene << " axis " << a << " tick " << i;
        if (!tick.label.text.empty()) labels.push_back(tick.label.box);
      }
      if (!axis.name.text.empty()) labels.push_back(axis.name.box);
    }
    for (std::size_t i = 0; i < labels.size(); ++i)
      for (std::size_t j = i + 1; j < labels.size(); ++j)
        EXPECT_FALSE(boxesOverlap(labels[i], labels[j], 0)) << scene;
  }
  EXPECT_GT(axesWithTicks, 400);
}

TEST(Axes, AnAxisSeenEndOnGetsNoTicks) {
  WorldTransform transform{{-5.0, 0.0, 10.0}, {0.5, 0.5, 0.25}};
  const glm::dvec3 lower(-5.0, 0.0, 10.0), upper(5.0, 8.0, 12.0);
  OrbitCamera camera;
  camera.projection = Projection::Orthographic;
  camera.up = Axis{2, 1.0f};
  camera.elevationDegrees = 90.0f;  // from +z
  camera = frameBox(camera, glm::vec3(transform.toCellUnits(lower)),
                    glm::vec3(transform.toCellUnits(upper)), 1.0f, 0.7f);
  const AxesLayout layout = layoutAxes(camera, 600, 600, lower, upper, transform, 12);
  EXPECT_FALSE(layout.axes[2].shown);
  EXPECT_TRUE(layout.axes[2].ticks.empty());
  EXPECT_TRUE(layout.axes[2].name.text.empty());
  for (int axis : {0, 1}) {
    EXPECT_TRUE(layout.axes[axis].shown) << axis;
    EXPECT_GE(layout.axes[axis].ticks.size(), 3u) << axis;
  }
  EXPECT_EQ(layout.axes[0].name.text, "x");
}

TEST(Triad, ViewedFromPlusXWithZUpYPointsRightAndZUp) {
  OrbitCamera camera;
  camera.up = Axis{2, 1.0f};
  camera.azimuthDegrees = 0.0f;
  camera.elevationDegrees = 0.0f;
  const TriadLayout layout = layoutTriad(camera, 800, 600, 13);
  const float arm = layout.armLength;
  ASSERT_GT(arm, 10.0f);
  const glm::vec2 x = layout.arms[0].tip - layout.origin;
  const glm::vec2 y = layout.arms[1].tip - layout.origin;
  const glm::vec2 z = layout.arms[2].tip - layout.origin;
  EXPECT_LT(glm::length(x), 1e-3f * arm);
  EXPECT_NEAR(y.x, arm, 1e-3f * arm);
  EXPECT_NEAR(y.y, 0.0f, 1e-3f * arm);
  EXPECT_NEAR(z.x, 0.0f, 1e-3f * arm);
  EXPECT_NEAR(z.y, -arm, 1e-3f * arm);  // rows grow downwards
  EXPECT_EQ(layout.arms[0].label.text, "x");
  EXPECT_EQ(layout.arms[2].label.text, "z");
  // In the bottom-left corner.
  EXPECT_LT(layout.origin.x, 800.0f / 4);
  EXPECT_GT(layout.origin.y, 600.0f * 3 / 4);

  Image image(800, 600, kBackground);
  drawTriad(image, layout);
  const Rgba8 green =
      image.at(std::uint32_t(layout.origin.x + 0.7f * arm), std::uint32_t(layout.origin.y));
  EXPECT_GT(green.g, green.r);
  EXPECT_GT(green.g, green.b);
  const Rgba8 blue =
      image.at(std::uint32_t(layout.origin.x), std::uint32_t(layout.origin.y - 0.7f * arm));
  EXPECT_GT(blue.b, blue.r);
  EXPECT_GT(blue.b, blue.g);
}

bool contains(const PixelRect& outer, const PixelRect& inner) {
  return inner.x >= outer.x && inner.y >= outer.y &&
         inner.x + inner.width <= outer.x + outer.width &&
         inner.y + inner.height <= outer.y + outer.height;
}

TEST(Triad, ArmsAndLabelsStayInsideItsCornerFromEveryDirection) {
  std::mt19937 random(3);
  for (int view = 0; view < 100; ++view) {
    const RandomScene s = randomScene(random);
    const int labelSize = overlayLabelPixelSize(s.width, s.height);
    const TriadLayout layout = layoutTriad(s.camera, s.width, s.height, labelSize);
    EXPECT_TRUE(contains({0, 0, int(s.width), int(s.height)}, layout.area)) << view;
    for (const TriadArm& arm : layout.arms) {
      EXPECT_LE(glm::length(arm.tip - layout.origin), layout.armLength * 1.0001f);
      EXPECT_TRUE(contains(layout.area, arm.label.box)) << view << " axis " << arm.axis;
    }
  }
}

TEST(ScaleBar, InAnOrthographicViewOfAKnownHeightTheBarIsARoundLength) {
  OrbitCamera camera;
  camera.projection = Projection::Orthographic;
  camera.distance = 50.0f;
  camera.fovYDegrees = 90.0f;  // the view is 2 * 50 * tan(45 degrees) = 100 units tall: 1 kpc
  const ScaleBarLayout layout = layoutScaleBar(camera, 1000, 1000, 0.01, "kpc", 16);
  EXPECT_DOUBLE_EQ(layout.length, 0.2);  // of 0.1 to 0.25 kpc (10 to 25 % of the width)
  EXPECT_NEAR(layout.end.x - layout.start.x, 200.0f, 1e-2f);
  EXPECT_EQ(layout.end.y, layout.start.y);
  EXPECT_EQ(layout.label.text, "0.2 kpc");
  EXPECT_EQ(layoutScaleBar(camera, 1000, 1000, 0.01, "", 16).label.text, "0.2");
}

TEST(ScaleBar, InOrthographicViewsTheBarIsItsLengthOverTheViewHeightTimesTheImageHeight) {
  std::mt19937 random(29);
  for (int view = 0; view < 200; ++view) {
    RandomScene s = randomScene(random);
    s.camera.projection = Projection::Orthographic;
    const int labelSize = overlayLabelPixelSize(s.width, s.height);
    const ScaleBarLayout layout =
        layoutScaleBar(s.camera, s.width, s.height, s.transform.spacing.y, "Mpc", labelSize);
    const double viewHeightCells =
        2.0 * s.camera.distance * std::tan(glm::radians(double(s.camera.fovYDegrees)) / 2.0);
    const double viewHeight = viewHeightCells * s.transform.spacing.y;
    const double expected = layout.length / viewHeight * s.height;
    EXPECT_NEAR(layout.end.x - layout.start.x, expected, 1e-4 * expected) << view;
    EXPECT_GE(expected, 0.1 * s.width * (1 - 1e-6)) << view;
    EXPECT_LE(expected, 0.25 * s.width * (1 + 1e-6)) << view;
    EXPECT_TRUE(isOneTwoFiveTimesPowerOfTen(layout.length)) << layout.length;
    EXPECT_EQ(layout.label.text, fmt::format("{:g} Mpc", layout.length));
    // Above the triad.
    const PixelRect triad = layoutTriad(s.camera, s.width, s.height, labelSize).area;
    EXPECT_LT(layout.start.y + 0.5f * layout.endHeight, float(triad.y));
    EXPECT_LT(layout.label.box.y + layout.label.box.height, triad.y);

    Image image(s.width, s.height, kBackground);
    drawScaleBar(image, layout, kInk);
    EXPECT_TRUE(isInk(image, 0.5f * (layout.start + layout.end))) << view;
  }
}

}  // namespace
}  // namespace amrstream::render
