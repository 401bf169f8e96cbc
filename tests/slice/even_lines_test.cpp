// Evenly spaced lines against fields whose lines are known: straight lines a separation apart in
// a uniform field, circles in a rotation, lines that stop at a hole in the data, and, in any
// field, no two lines closer than d_test (brute force over all pairs of points).

#include "slice/even_lines.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace amrstream::slice {
namespace {

const glm::dvec2 kCentre(0.5, 0.5);

double stepOf(const EvenLinesOptions& options) { return options.stepRatio * options.separation; }
double testDistanceOf(const EvenLinesOptions& options) {
  return options.testRatio * options.separation;
}

double lengthOf(const PlaneLine& line) {
  double length = 0.0;
  for (std::size_t i = 1; i < line.points.size(); ++i)
    length += glm::distance(line.points[i - 1], line.points[i]);
  return length;
}

double distanceToWindowEdge(glm::dvec2 p) { return std::min({p.x, p.y, 1.0 - p.x, 1.0 - p.y}); }

std::optional<glm::dvec2> rotation(glm::dvec2 p) { return glm::dvec2(-(p.y - 0.5), p.x - 0.5); }

std::optional<glm::dvec2> cellular(glm::dvec2 p) {
  return glm::dvec2(std::sin(2.0 * std::numbers::pi * p.y), std::cos(2.0 * std::numbers::pi * p.x));
}

// The smallest distance between points of different lines.
double closestApproach(const std::vector<PlaneLine>& lines) {
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < lines.size(); ++a)
    for (std::size_t b = a + 1; b < lines.size(); ++b)
      for (const glm::dvec2& p : lines[a].points)
        for (const glm::dvec2& q : lines[b].points)
          closest = std::min(closest, glm::distance(p, q));
  return closest;
}

TEST(EvenLines, AUniformFieldGivesStraightLinesASeparationApartAcrossTheWindow) {
  const EvenLinesOptions options;
  const double step = stepOf(options);
  const std::vector<PlaneLine> lines =
      evenlySpacedLines([](glm::dvec2) { return glm::dvec2(1.0, 0.0); }, options);
  ASSERT_GE(lines.size(), 19u);
  std::vector<double> heights;
  for (const PlaneLine& line : lines) {
    const double y = line.points.front().y;
    for (const glm::dvec2& p : line.points) EXPECT_NEAR(p.y, y, 1e-12);
    EXPECT_LE(line.points.front().x, step);
    EXPECT_GE(line.points.back().x, 1.0 - step);
    heights.push_back(y);
  }
  std::sort(heights.begin(), heights.end());
  for (std::size_t i = 1; i < heights.size(); ++i)
    EXPECT_NEAR(heights[i] - heights[i - 1], options.separation, 1e-9) << i;
  EXPECT_LE(heights.front(), options.separation + 1e-9);
  EXPECT_GE(heights.back(), 1.0 - options.separation - 1e-9);
}

TEST(EvenLines, ADiagonalFieldGivesDiagonalLinesASeparationApart) {
  const EvenLinesOptions options;
  const double step = stepOf(options);
  const std::vector<PlaneLine> lines =
      evenlySpacedLines([](glm::dvec2) { return glm::dvec2(1.0, 1.0); }, options);
  ASSERT_GE(lines.size(), 20u);
  // The signed distance of p from the diagonal through the centre.
  const auto offsetOf = [](glm::dvec2 p) { return (p.y - p.x) / std::numbers::sqrt2; };
  std::vector<double> offsets;
  for (const PlaneLine& line : lines) {
    const double offset = offsetOf(line.points.front());
    for (const glm::dvec2& p : line.points) EXPECT_NEAR(offsetOf(p), offset, 1e-9);
    EXPECT_GT(line.points.back().x, line.points.front().x);
    EXPECT_LE(distanceToWindowEdge(line.points.front()), step);
    EXPECT_LE(distanceToWindowEdge(line.points.back()), step);
    offsets.push_back(offset);
  }
  std::sort(offsets.begin(), offsets.end());
  for (std::size_t i = 1; i < offsets.size(); ++i)
    EXPECT_NEAR(offsets[i] - offsets[i - 1], options.separation, 1e-6) << i;
  // A line at offset c crosses the window's corner triangle over sqrt(2) (1 - sqrt(2) |c|): the
  // lines kept (a separation long at least) reach to within 1.5 separations of the corners.
  const double farthest = std::numbers::sqrt2 / 2.0 - 1.5 * options.separation - 1e-9;
  EXPECT_LE(offsets.front(), -farthest);
  EXPECT_GE(offsets.back(), farthest);
}

TEST(EvenLines, ARotationGivesCirclesThatCloseAndKeepApart) {
  const EvenLinesOptions options;
  const double step = stepOf(options), testDistance = testDistanceOf(options);
  const std::vector<PlaneLine> lines = evenlySpacedLines(rotation, options);
  ASSERT_GE(lines.size(), 8u);
  // Circles wider than the window break into arcs, one in each corner: radii must differ among
  // the whole circles and among the arcs of one corner.
  std::vector<double> radiiByPlace[5];
  std::size_t loops = 0;
  for (const PlaneLine& line : lines) {
    const double radius = glm::distance(line.points.front(), kCentre);
    for (const glm::dvec2& p : line.points) EXPECT_NEAR(glm::distance(p, kCentre), radius, 1e-5);
    if (radius + step >= 0.5) {
      const glm::dvec2 middle = line.points[line.points.size() / 2];
      radiiByPlace[1 + (middle.x > 0.5) + 2 * (middle.y > 0.5)].push_back(radius);
      continue;
    }
    radiiByPlace[0].push_back(radius);
    ++loops;
    EXPECT_GE(lengthOf(line), 2.0 * std::numbers::pi * radius - testDistance - 2.0 * step);
    EXPECT_LE(glm::distance(line.points.front(), line.points.back()), testDistance + 2.0 * step)
        << "radius " << radius;
  }
  EXPECT_GE(loops, 8u);  // 0.5 / separation circles fit inside
  for (std::vector<double>& radii : radiiByPlace) {
    std::sort(radii.begin(), radii.end());
    for (std::size_t i = 1; i < radii.size(); ++i)
      EXPECT_GE(radii[i] - radii[i - 1], testDistance - step) << i;
  }
  EXPECT_GE(closestApproach(lines), testDistance - step);
}

TEST(EvenLines, LinesStopWhereTheDataEndAndGoOnBeyond) {
  const double holeRadius = 0.2;
  const auto withHole = [&](glm::dvec2 p) -> std::optional<glm::dvec2> {
    if (glm::distance(p, kCentre) < holeRadius) return std::nullopt;
    return glm::dvec2(1.0, 0.0);
  };
  const EvenLinesOptions options;
  const double step = stepOf(options), testDistance = testDistanceOf(options);
  const std::vector<PlaneLine> lines = evenlySpacedLines(withHole, options);
  std::size_t leftOfHole = 0, rightOfHole = 0;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::vector<glm::dvec2>& points = lines[n].points;
    for (const glm::dvec2& p : points) EXPECT_GE(glm::distance(p, kCentre), holeRadius - step);
    // A line ends at the window's edge, at the hole's, or (beside the hole, where a line from the
    // other side passes) near another line.
    for (const glm::dvec2 end : {points.front(), points.back()}) {
      const bool atWindowEdge = distanceToWindowEdge(end) <= step;
      const bool atHole = glm::distance(end, kCentre) <= holeRadius + step;
      bool nearLine = false;
      for (std::size_t m = 0; m < lines.size(); ++m)
        for (const glm::dvec2& q : lines[m].points)
          nearLine |= m != n && glm::distance(end, q) <= testDistance + step;
      EXPECT_TRUE(atWindowEdge || atHole || nearLine) << end.x << ", " << end.y;
    }
    const bool besideHole = std::abs(points.front().y - 0.5) < 0.5 * holeRadius;
    leftOfHole += besideHole && points.back().x < 0.5 &&
                  glm::distance(points.back(), kCentre) <= holeRadius + step;
    rightOfHole += besideHole && points.front().x > 0.5 &&
                   glm::distance(points.front(), kCentre) <= holeRadius + step;
  }
  EXPECT_GE(leftOfHole, 2u);
  EXPECT_GE(rightOfHole, 2u);
}

TEST(EvenLines, NoTwoLinesComeWithinTheTestDistance) {
  const EvenLinesOptions options;
  const double step = stepOf(options), testDistance = testDistanceOf(options);
  const std::vector<PlaneLine> lines = evenlySpacedLines(cellular, options);
  ASSERT_GE(lines.size(), 10u);
  EXPECT_GE(closestApproach(lines), testDistance - step);
  const std::size_t selfSteps = std::size_t(std::ceil(2.0 * options.separation / step)) + 1;
  for (const PlaneLine& line : lines) {
    EXPECT_GE(lengthOf(line), options.separation);
    for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
      const glm::dvec2 along = line.points[i + 1] - line.points[i];
      EXPECT_GT(glm::dot(along, *cellular(line.points[i])), 0.0);  // in the field's direction
      for (std::size_t j = i + selfSteps; j < line.points.size(); ++j)
        EXPECT_GE(glm::distance(line.points[i], line.points[j]), testDistance - step);
    }
  }
}

TEST(EvenLines, LinesKeepToTheirPointCount) {
  EvenLinesOptions options;
  options.maxPointsPerLine = 50;
  const std::vector<PlaneLine> lines = evenlySpacedLines(cellular, options);
  ASSERT_FALSE(lines.empty());
  for (const PlaneLine& line : lines) EXPECT_LE(line.points.size(), 50u);
}

TEST(EvenLines, TwoRunsGiveTheSameLines) {
  const EvenLinesOptions options;
  const std::vector<PlaneLine> first = evenlySpacedLines(cellular, options);
  const std::vector<PlaneLine> second = evenlySpacedLines(cellular, options);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t n = 0; n < first.size(); ++n) EXPECT_EQ(first[n].points, second[n].points) << n;
}

TEST(EvenLines, BadOptionsThrow) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto withOptions = [](auto change) {
    EvenLinesOptions options;
    change(options);
    return options;
  };
  const std::vector<EvenLinesOptions> bad{
      withOptions([](EvenLinesOptions& o) { o.upper = o.lower; }),
      withOptions([](EvenLinesOptions& o) { o.upper.y = -1.0; }),
      withOptions([&](EvenLinesOptions& o) { o.lower.x = nan; }),
      withOptions([&](EvenLinesOptions& o) { o.upper.x = inf; }),
      withOptions([](EvenLinesOptions& o) { o.separation = 0.0; }),
      withOptions([](EvenLinesOptions& o) { o.separation = -0.1; }),
      withOptions([&](EvenLinesOptions& o) { o.separation = nan; }),
      withOptions([&](EvenLinesOptions& o) { o.separation = inf; }),
      withOptions([](EvenLinesOptions& o) { o.testRatio = 0.0; }),
      withOptions([](EvenLinesOptions& o) { o.testRatio = 1.5; }),
      withOptions([&](EvenLinesOptions& o) { o.testRatio = nan; }),
      withOptions([](EvenLinesOptions& o) { o.stepRatio = -0.1; }),
      withOptions([](EvenLinesOptions& o) { o.stepRatio = 2.0; }),
  };
  for (std::size_t n = 0; n < bad.size(); ++n)
    EXPECT_THROW(evenlySpacedLines(rotation, bad[n]), std::invalid_argument) << n;
  EXPECT_THROW(evenlySpacedLines(PlaneVectorField{}, EvenLinesOptions{}), std::invalid_argument);
  EvenLinesOptions edge;
  edge.testRatio = 1.0;
  edge.stepRatio = 1.0;
  EXPECT_NO_THROW(evenlySpacedLines(rotation, edge));
}

}  // namespace
}  // namespace amrstream::slice
