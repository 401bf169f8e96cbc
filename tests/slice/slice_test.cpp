// Slices against what is known of them: the plane's axes and pixels; the samples at the pixel
// centres equal the reconstruction there; the in-plane field lines of a rotation, reconstructed
// exactly by the linear interpolant across levels, are circles; the figure puts the data's
// pixels where its frame says.

#include <gtest/gtest.h>

#include <cmath>

#include "amrstream/error.hpp"
#include "flow/sampler.hpp"
#include "slice/even_lines.hpp"
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
  const flow::GridSamples samples = flow::sampleGrid(volume, plane.grid());
  std::size_t checked = 0;
  for (std::uint32_t j = 0; j < plane.height; j += 3) {
    for (std::uint32_t i = 0; i < plane.width; i += 3) {
      const glm::dvec3 p = plane.physical(plane.pixelCentre(i, j));
      const flow::VectorSample expected = flow::sampleVector(
          volume, flow::wrapPeriodic(volume, flow::toCellPoint(volume.transform.toCellUnits(p))));
      const std::size_t n = i + std::size_t(plane.width) * j;
      ASSERT_EQ(bool(samples.valid[n]), expected.valid) << i << ", " << j;
      if (!expected.valid) continue;
      EXPECT_NEAR(glm::length(samples.vectors[n] - expected.value), 0.0f, 1e-5f);
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
