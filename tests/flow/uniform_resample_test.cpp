// The uniform resample against fields known at its points: cell values at cell centres, a
// linear field anywhere with the linear interpolant, and zeros with an invalid mark where no
// region covers a point.

#include "flow/uniform_resample.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "flow_test_support.hpp"

namespace amrstream::flow {
namespace {

glm::dvec3 wavy(glm::dvec3 p) {
  return {std::sin(0.7 * p.x + 0.3 * p.z), std::cos(0.5 * p.y) - 0.2 * p.x, 0.1 * p.x * p.y};
}

glm::dvec3 linearField(glm::dvec3 p) {
  return {0.3 + 0.02 * p.x - 0.015 * p.y + 0.01 * p.z,
          -0.2 + 0.012 * p.x + 0.025 * p.y - 0.02 * p.z,
          0.1 - 0.018 * p.x + 0.008 * p.y + 0.03 * p.z};
}

glm::dvec3 pointOf(const UniformGridSpec& spec, std::size_t n) {
  const std::size_t nx = spec.dims[0], ny = spec.dims[1];
  return spec.origin() +
         spec.spacing() * glm::dvec3(double(n % nx), double(n / nx % ny), double(n / (nx * ny)));
}

TEST(UniformResample, PointsAtCellCentresTakeTheCellsValues) {
  const bricks::AmrField field =
      testing::uniformGrid(6, [](glm::dvec3 c) { return glm::vec3(wavy(c)); });
  const VectorVolume volume = testing::volumeOf(field);
  const UniformGridSpec spec{glm::dvec3(0.0), glm::dvec3(6.0), {6, 6, 6}};
  const UniformGrid grid = resampleUniform(volume, spec);
  ASSERT_EQ(grid.vectors.size(), 216u);
  EXPECT_EQ(grid.validCount, 216u);
  for (std::size_t n = 0; n < grid.vectors.size(); ++n) {
    const glm::vec3 expected(wavy(pointOf(spec, n)));
    for (int a = 0; a < 3; ++a) EXPECT_FLOAT_EQ(grid.vectors[n][a], expected[a]) << n;
  }
}

TEST(UniformResample, LinearInterpolantGivesALinearFieldAnywhereOnAMultiLevelLayout) {
  testing::RandomAmrOptions layout;
  layout.levels = 4;
  const bricks::AmrField field =
      testing::randomAmr(3, layout, [](glm::dvec3 c) { return glm::vec3(linearField(c)); });
  VolumeOptions options;
  options.interpolant = Interpolant::Linear;
  options.pointData = {"vy"};
  const VectorVolume volume = buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"}, options);
  const glm::dvec3 lower(volume.domain.lower), upper(volume.domain.upper);
  const UniformGridSpec spec{lower, upper, {13, 7, 5}};
  std::size_t rows = 0;
  const UniformGrid grid = resampleUniform(volume, spec, [&](std::size_t done) { rows = done; });
  EXPECT_EQ(rows, 7u * 5u);  // the last report counts every row
  EXPECT_EQ(grid.validCount, spec.pointCount());
  ASSERT_EQ(grid.channels.size(), spec.pointCount());
  for (std::size_t n = 0; n < grid.vectors.size(); ++n) {
    const glm::dvec3 exact = linearField(pointOf(spec, n));
    EXPECT_LT(glm::length(glm::dvec3(grid.vectors[n]) - exact), 2e-5) << n;
    EXPECT_NEAR(grid.channels[n], exact.y, 2e-5) << n;
  }
}

TEST(UniformResample, PointsInNoRegionAreInvalidAndZero) {
  const VectorVolume volume = testing::volumeOf(testing::twoBlocksWithAGap());
  // Point x at 0.5, 1.5, ..., 11.5: the gap 4.5 <= x < 7.5 is in no region, and at x = 7.5
  // every tent of the second block is zero.
  const UniformGridSpec spec{glm::dvec3(0.0), glm::dvec3(12.0, 4.0, 4.0), {12, 4, 4}};
  const UniformGrid grid = resampleUniform(volume, spec);
  std::uint64_t valid = 0;
  for (std::size_t n = 0; n < grid.vectors.size(); ++n) {
    const double x = pointOf(spec, n).x;
    const bool inside = x < 4.5 || x > 7.5;
    EXPECT_EQ(grid.valid[n], inside ? 1 : 0) << "x = " << x;
    EXPECT_EQ(grid.vectors[n], inside ? glm::vec3(1.0f) : glm::vec3(0.0f)) << "x = " << x;
    valid += inside;
  }
  EXPECT_EQ(grid.validCount, valid);
  EXPECT_EQ(valid, 8u * 16u);  // x = 0.5 .. 3.5 and 8.5 .. 11.5
}

}  // namespace
}  // namespace amrstream::flow
