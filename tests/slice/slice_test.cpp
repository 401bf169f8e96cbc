// Slices against what is known of them: the plane's axes and pixels; the samples at the pixel
// centres equal the reconstruction there; the in-plane field lines of a rotation, reconstructed
// exactly by the linear interpolant across levels, are circles; the figure puts the data's
// pixels where its frame says.

#include <gtest/gtest.h>

#include <cmath>

#include "amrstream/error.hpp"
#include "flow/sampler.hpp"
#include "slice/even_lines.hpp"
#include "slice/line_samples.hpp"
#include "slice/plane_field.hpp"
#include "slice/slice_figure.hpp"
#include "slice/slice_plane.hpp"
#include "tests/flow/flow_test_support.hpp"

namespace amrstream::slice {
namespace {

const glm::dvec3 kLower(0.0), kUpper(16.0, 16.0, 8.0);

TEST(SlicePlane, AcrossAnAxisItsAxesAreYts) {
  SliceRequest request;
  request.width = 64;
  request.normal = "x";
  SlicePlane plane = slicePlane(request, kLower, kUpper);
  EXPECT_EQ(plane.axisNames()[0], "y");
  EXPECT_EQ(plane.axisNames()[1], "z");
  EXPECT_EQ(plane.lower, glm::dvec2(0.0, 0.0));
  EXPECT_EQ(plane.upper, glm::dvec2(16.0, 8.0));
  EXPECT_EQ(plane.height, 32u);
  EXPECT_EQ(plane.physical({3.0, 5.0}), glm::dvec3(8.0, 3.0, 5.0));
  request.normal = "y";
  plane = slicePlane(request, kLower, kUpper);
  EXPECT_EQ(plane.axisNames()[0], "z");
  EXPECT_EQ(plane.axisNames()[1], "x");
  EXPECT_EQ(plane.physical({3.0, 5.0}), glm::dvec3(5.0, 8.0, 3.0));
  request.normal = "z";
  request.point = glm::dvec3(1.0, 2.0, 3.0);
  request.window = std::array<double, 4>{2.0, 4.0, 10.0, 8.0};
  plane = slicePlane(request, kLower, kUpper);
  EXPECT_EQ(plane.physical({3.0, 5.0}), glm::dvec3(3.0, 5.0, 3.0));
  EXPECT_EQ(plane.height, 32u);
  EXPECT_EQ(plane.pixelCentre(0, 0), glm::dvec2(2.0625, 4.0625));
  const flow::AffineGrid grid = plane.grid();
  EXPECT_EQ(grid.origin, glm::dvec3(2.0625, 4.0625, 3.0));
  EXPECT_EQ(grid.dims[0], 64u);
  EXPECT_EQ(grid.dims[1], 32u);
}

TEST(SlicePlane, AnyNormalGivesARightHandedFrameInThePlane) {
  SliceRequest request;
  request.normal = "1,2,2";
  const SlicePlane plane = slicePlane(request, kLower, kUpper);
  EXPECT_EQ(plane.axis, -1);
  EXPECT_NEAR(glm::length(plane.normal - glm::dvec3(1, 2, 2) / 3.0), 0.0, 1e-15);
  EXPECT_NEAR(glm::dot(plane.u, plane.normal), 0.0, 1e-15);
  EXPECT_NEAR(glm::dot(plane.v, plane.normal), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(glm::cross(plane.u, plane.v) - plane.normal), 0.0, 1e-15);
  EXPECT_GT(plane.v.z, 0.0);  // up is as near +z as the plane allows
  const glm::dvec3 p = plane.physical({1.0, -2.0});
  EXPECT_NEAR(glm::dot(p - plane.point, plane.normal), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(plane.planeCoordinates(p) - glm::dvec2(1.0, -2.0)), 0.0, 1e-12);
}

TEST(SlicePlane, BadRequestsAreRefusedNamingTheOption) {
  SliceRequest request;
  request.normal = "0,0,0";
  EXPECT_THROW(slicePlane(request, kLower, kUpper), InputError);
  request.normal = "w";
  EXPECT_THROW(slicePlane(request, kLower, kUpper), InputError);
  request.normal = "z";
  request.point = glm::dvec3(20.0, 1.0, 1.0);
  EXPECT_THROW(slicePlane(request, kLower, kUpper), InputError);
  request.point.reset();
  request.window = std::array<double, 4>{30.0, 0.0, 40.0, 1.0};
  EXPECT_THROW(slicePlane(request, kLower, kUpper), InputError);
  request.window = std::array<double, 4>{1.0, 0.0, 1.0, 1.0};
  EXPECT_THROW(slicePlane(request, kLower, kUpper), InputError);
  request.window.reset();
  request.width = 0;
  EXPECT_THROW(slicePlane(request, kLower, kUpper), InputError);
}

glm::vec3 rotation(glm::dvec3 c) { return glm::vec3(float(-(c.y - 8.0)), float(c.x - 8.0), 0.25f); }

// A multi-level layout of the rotation about (8, 8) (in finest cells), with the linear
// interpolant, which reproduces it exactly across level jumps.
flow::VectorVolume rotationVolume() {
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  layout.rootCells = glm::ivec3(4, 4, 2);
  static const bricks::AmrField field = testing::randomAmr(7, layout, rotation);
  flow::VolumeOptions options;
  options.interpolant = flow::Interpolant::Linear;
  return flow::buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"}, options);
}

TEST(SliceSampling, PixelsHoldTheReconstructionAtTheirCentres) {
  const flow::VectorVolume volume = rotationVolume();
  SliceRequest request;
  request.width = 40;
  request.normal = "0.3,0.2,1";
  const glm::dvec3 lower = volume.transform.toPhysical(glm::dvec3(volume.domain.lower));
  const glm::dvec3 upper = volume.transform.toPhysical(glm::dvec3(volume.domain.upper));
  const SlicePlane plane = slicePlane(request, lower, upper);
  const flow::GridSamples samples = samplePixels(volume, pixelGrid(volume, plane));
  std::size_t checked = 0;
  for (std::uint32_t j = 0; j < plane.height; j += 3) {
    for (std::uint32_t i = 0; i < plane.width; i += 3) {
      const glm::dvec3 p = plane.physical(plane.pixelCentre(i, j));
      const flow::VectorSample expected = flow::sampleVector(
          volume, flow::wrapPeriodic(volume, flow::toCellPoint(volume.transform.toCellUnits(p))));
      const std::size_t n = i + std::size_t(plane.width) * j;
      ASSERT_EQ(bool(samples.valid[n]), expected.valid) << i << ", " << j;
      if (!expected.valid) continue;
      // The pixel's point in float, the oracle's in double: the same within a float's rounding.
      EXPECT_NEAR(glm::length(samples.vectors[n] - expected.value), 0.0f, 1e-5f);
      EXPECT_NEAR(glm::length(samples.vectors[n] - rotation(volume.transform.toCellUnits(p))), 0.0f,
                  1e-4f);
      ++checked;
    }
  }
  EXPECT_GT(checked, 50u);
}

TEST(SliceLines, TheInPlaneLinesOfARotationAreCircles) {
  const flow::VectorVolume volume = rotationVolume();
  SliceRequest request;
  request.width = 64;
  request.point = glm::dvec3(8.0, 8.0, 4.0);
  const glm::dvec3 lower = volume.transform.toPhysical(glm::dvec3(volume.domain.lower));
  const glm::dvec3 upper = volume.transform.toPhysical(glm::dvec3(volume.domain.upper));
  const SlicePlane plane = slicePlane(request, lower, upper);
  const glm::dvec2 centre = plane.planeCoordinates(
      volume.transform.toPhysical(glm::dvec3(8.0, 8.0, 4.0) + glm::dvec3(volume.domain.lower)));
  EvenLinesOptions options;
  options.lower = plane.lower;
  options.upper = plane.upper;
  options.separation = (plane.upper.x - plane.lower.x) / 12.0;
  const std::vector<PlaneLine> lines = evenlySpacedLines(exactInPlane(volume, plane), options);
  ASSERT_GE(lines.size(), 4u);
  std::size_t circles = 0;
  for (const PlaneLine& line : lines) {
    const double radius = glm::distance(line.points.front(), centre);
    for (const glm::dvec2& p : line.points)
      EXPECT_NEAR(glm::distance(p, centre), radius, 1e-4 * (plane.upper.x - plane.lower.x));
    const bool inside = radius + options.separation < 0.5 * (plane.upper.x - plane.lower.x);
    circles += inside;
  }
  EXPECT_GE(circles, 2u);
}

TEST(SliceLines, SamplesAlongThemAreTheReconstruction) {
  const flow::VectorVolume volume = rotationVolume();
  SliceRequest request;
  request.width = 64;
  request.point = glm::dvec3(8.0, 8.0, 4.0);
  const SlicePlane plane =
      slicePlane(request, volume.transform.toPhysical(glm::dvec3(volume.domain.lower)),
                 volume.transform.toPhysical(glm::dvec3(volume.domain.upper)));
  EvenLinesOptions options;
  options.lower = plane.lower;
  options.upper = plane.upper;
  options.separation = (plane.upper.x - plane.lower.x) / 10.0;
  const std::vector<PlaneLine> lines = evenlySpacedLines(exactInPlane(volume, plane), options);
  const LineSamples samples = sampleAlongLines(volume, plane, lines);
  ASSERT_EQ(samples.offsets.size(), lines.size() + 1);
  const std::vector<std::vector<float>> speeds = valuesAlongLines(samples, 0, -1);
  std::size_t checked = 0;
  for (std::size_t line = 0; line < lines.size(); ++line) {
    ASSERT_EQ(speeds[line].size(), lines[line].points.size());
    for (std::size_t k = 0; k < lines[line].points.size(); ++k) {
      const std::uint64_t n = samples.offsets[line] + k;
      EXPECT_NEAR(glm::distance(samples.positions[n], plane.physical(lines[line].points[k])), 0.0,
                  1e-12);
      if (std::isnan(samples.vectors[n].x)) continue;
      const glm::vec3 expected = rotation(volume.transform.toCellUnits(samples.positions[n]));
      EXPECT_NEAR(glm::length(samples.vectors[n] - expected), 0.0f, 1e-4f);
      EXPECT_NEAR(speeds[line][k], glm::length(expected), 1e-4f);
      ++checked;
    }
  }
  EXPECT_GT(checked, 200u);
}

TEST(SliceFigure, LinesTakeTheColoursAndWidthsOfTheirValues) {
  SliceRequest request;
  request.width = 200;
  const SlicePlane plane = slicePlane(request, kLower, kUpper);
  SliceLayers layers;
  const auto across = [&](double b) {
    PlaneLine line;
    for (int k = 0; k <= 20; ++k)
      line.points.push_back({plane.lower.x + (plane.upper.x - plane.lower.x) * k / 20.0, b});
    return line;
  };
  const double b0 = plane.lower.y + 0.25 * (plane.upper.y - plane.lower.y);
  const double b1 = plane.lower.y + 0.75 * (plane.upper.y - plane.lower.y);
  layers.lines = {across(b0), across(b1)};
  layers.lineWidthPixels = 7.0f;
  const auto row = [&](double b) {
    const double t = (b - plane.lower.y) / (plane.upper.y - plane.lower.y);
    return std::uint32_t(sliceFigureFrame(plane, layers).top) + plane.height - 1 -
           std::uint32_t(t * plane.height);
  };
  // The column a third of the way across, away from the arrows.
  const std::uint32_t x = std::uint32_t(sliceFigureFrame(plane, layers).left) + plane.width / 3;

  SliceLayers coloured = layers;
  coloured.lineColourValues = {std::vector<float>(21, 2.0f), std::vector<float>(21, 4.0f)};
  coloured.lineColours.map = render::ColourMap::Plasma;
  coloured.lineColours.scale.min = 2.0;
  coloured.lineColours.scale.max = 4.0;
  const render::Image colours = drawSliceFigure(plane, coloured);
  EXPECT_EQ(colours.at(x, row(b0)),
            render::toRgba8(render::sampleColourMap(render::ColourMap::Plasma, 0.0f)));
  EXPECT_EQ(colours.at(x, row(b1)),
            render::toRgba8(render::sampleColourMap(render::ColourMap::Plasma, 1.0f)));

  SliceLayers widened = layers;
  widened.lineWidthValues = {std::vector<float>(21, 10.0f), std::vector<float>(21, 30.0f)};
  widened.lineWidthRange = {10.0f, 30.0f};
  const render::Image widths = drawSliceFigure(plane, widened);
  // The dark pixels of each line in the column: a fifth of 7 pixels, and 7.
  const auto thickness = [&](std::uint32_t centre) {
    int count = 0;
    for (std::uint32_t y = centre - 10; y <= centre + 10; ++y) count += widths.at(x, y).r < 110;
    return count;
  };
  EXPECT_GE(thickness(row(b0)), 1);
  EXPECT_LE(thickness(row(b0)), 2);
  EXPECT_GE(thickness(row(b1)), 6);
  EXPECT_LE(thickness(row(b1)), 8);
}

TEST(SliceFigure, TheDataSitWhereTheFrameSays) {
  SliceRequest request;
  request.width = 200;
  const SlicePlane plane = slicePlane(request, kLower, kUpper);
  SliceLayers layers;
  layers.background.assign(std::size_t(plane.width) * plane.height, 0.0f);
  layers.background[0] = 1.0f;  // the window's lower left pixel, at the top of the colours
  layers.colours.scale.min = 0.0;
  layers.colours.scale.max = 1.0;
  const render::Image image = drawSliceFigure(plane, layers);
  const FigureFrame frame = sliceFigureFrame(plane, layers);
  EXPECT_GT(image.width, plane.width);
  EXPECT_GT(image.height, plane.height);
  const render::Rgba8 low = render::toRgba8(render::sampleColourMap(layers.colours.map, 0.0f));
  const render::Rgba8 high = render::toRgba8(render::sampleColourMap(layers.colours.map, 1.0f));
  const std::uint32_t left = std::uint32_t(frame.left),
                      bottom = std::uint32_t(frame.top) + plane.height - 1;
  EXPECT_EQ(image.at(left + 1, bottom), low);
  EXPECT_EQ(image.at(left, bottom), high);
  EXPECT_EQ(image.at(left + plane.width / 2, std::uint32_t(frame.top) + plane.height / 2), low);
}

}  // namespace
}  // namespace amrstream::slice
