// Gradient vectors (--vector grad(NAME), -grad(NAME)). Oracle: the gradient of a linear scalar
// f = a . x is the constant a in every cell, per physical length, whatever the cell's level and
// its neighbours' (random layouts of four levels, with jumps of more than one level across
// faces) and on a grid whose cells are not cubes in physical units; across a periodic face it
// takes the cells on the other side; and
// the requests that name no scalar channel are refused naming --vector.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "flow/gradient_request.hpp"
#include "flow/vector_volume.hpp"
#include "input_error_of.hpp"
#include "random_amr.hpp"
#include "volume_options.hpp"

namespace amrstream::flow {
namespace {

using ::testing::HasSubstr;

// A random four-level layout whose finest cells are `spacing` wide in physical units, with the
// scalar f = slope . x (x physical, at the cell centres) beside the random vector channels.
bricks::AmrField linearScalar(std::uint64_t seed, glm::dvec3 slope, glm::dvec3 spacing) {
  const bricks::AmrField layout = testing::randomAmr(seed);
  const WorldTransform transform{glm::dvec3(-3.0, 5.0, 0.5), spacing};
  std::vector<float> f(layout.cellCount());
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double width = double(1 << layout.levels()[i]);
    const glm::dvec3 centre = transform.toPhysical(glm::dvec3(layout.lowers()[i]) + 0.5 * width);
    f[i] = float(glm::dot(slope, centre));
  }
  std::vector<Channel> channels = layout.channels();
  channels.push_back({"f", std::move(f)});
  return bricks::AmrField({layout.lowers().begin(), layout.lowers().end()},
                          {layout.levels().begin(), layout.levels().end()}, std::move(channels),
                          transform, layout.source());
}

ChannelCatalog catalogNamed(std::vector<std::string> names) { return {"test-data", names}; }

// Every value slot holds `expected` to within float rounding of f's values (|f| < 80 here, so
// differences of f carry errors near 80 * 2^-24 over cells at least 0.25 wide).
void expectEverySlot(const VectorVolume& volume, glm::dvec3 expected) {
  ASSERT_FALSE(volume.values.empty());
  for (std::size_t slot = 0; slot < volume.values.size(); ++slot)
    for (int axis = 0; axis < 3; ++axis)
      ASSERT_NEAR(volume.values[slot][axis], expected[axis], 2e-4)
          << "slot " << slot << " axis " << axis;
}

TEST(GradientVector, OfALinearScalarIsItsSlopeInEveryCellOfEveryLevel) {
  const glm::dvec3 slope(0.7, -1.3, 2.1);
  const glm::dvec3 spacing(0.5, 0.25, 1.0);  // not cubes: the gradient is per physical length
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    const bricks::AmrField field = linearScalar(seed, slope, spacing);
    std::set<int> levels(field.levels().begin(), field.levels().end());
    ASSERT_EQ(levels.size(), 4u);
    const VectorChannels gradient = chooseVectorChannels(field, "grad(f)");
    expectEverySlot(buildVectorVolume(field, gradient), slope);
    const VectorChannels negative = chooseVectorChannels(field, "-grad(f)");
    expectEverySlot(buildVectorVolume(field, negative), -slope);
    // Per finest cell (not divided by the spacing) it would be slope * spacing: 0.35 in x.
  }
}

// Along a periodic axis the neighbours across the face are the cells on the other side: a scalar
// linear in x jumps there by its slope times the period, so the cells on the x faces see that
// jump (one-sided fits would give them the slope; across a level jump a neighbour's offset has
// other components too, which the jump also reaches), and every other cell the slope.
TEST(GradientVector, AcrossPeriodicFacesTakesTheCellsOnTheOtherSide) {
  const glm::dvec3 slope(0.7, 3.0, -0.5);
  const bricks::AmrField field = linearScalar(4, slope, glm::dvec3(1.0));
  const VolumeOptions periodicX = testing::periodicVolume({true, false, false});
  const VectorVolume volume =
      buildVectorVolume(field, chooseVectorChannels(field, "grad(f)"), periodicX);
  EXPECT_GT(volume.bricks.size(), volume.originalBrickCount);  // images across the x faces
  std::size_t onFaces = 0;
  for (std::size_t b = 0; b < volume.originalBrickCount; ++b) {
    const shared::Brick& brick = volume.bricks[b];
    const int width = 1 << brick.level;
    for (int z = 0; z < brick.size.z; ++z)
      for (int y = 0; y < brick.size.y; ++y)
        for (int x = 0; x < brick.size.x; ++x) {
          const int lower = brick.lower.x + x * width;
          const glm::vec3 g =
              volume.values[brick.valueOffset + x + brick.size.x * (y + brick.size.y * z)];
          if (lower == volume.domain.lower.x || lower + width == volume.domain.upper.x) {
            ++onFaces;
            ASSERT_GT(std::abs(g.x - slope.x), 0.1) << "a cell on an x face";
            continue;
          }
          for (int axis = 0; axis < 3; ++axis) ASSERT_NEAR(g[axis], slope[axis], 2e-4);
        }
  }
  EXPECT_GT(onFaces, 0u);
}

// The gradient vector also takes the linear interpolant: the gradient's own gradients are those
// of a constant, zero.
TEST(GradientVector, WithTheLinearInterpolantHasNoGradientOfItsOwn) {
  const bricks::AmrField field = linearScalar(5, glm::dvec3(1.0, 2.0, 0.0), glm::dvec3(0.5));
  VolumeOptions linear;
  linear.interpolant = Interpolant::Linear;
  const VectorVolume volume =
      buildVectorVolume(field, chooseVectorChannels(field, "-grad(f)"), linear);
  expectEverySlot(volume, glm::dvec3(-1.0, -2.0, 0.0));
  for (const glm::vec3& g : volume.vectorGradients)
    for (int axis = 0; axis < 3; ++axis) ASSERT_NEAR(g[axis], 0.0, 2e-4);
}

TEST(GradientVector, IsNamedAfterItsScalar) {
  const ChannelCatalog channels = catalogNamed({"temp", "Y(H2)"});
  const VectorChannels gradient = chooseVectorChannels(channels, "grad(temp)");
  EXPECT_EQ(gradient.name, "grad(temp)");
  EXPECT_EQ(gradient.channels,
            (std::array<std::string, 3>{"d(temp)/dx", "d(temp)/dy", "d(temp)/dz"}));
  EXPECT_EQ(gradient.sourceChannels(), std::vector<std::string>{"temp"});
  EXPECT_EQ(gradient.gradientSign, 1.0f);
  const VectorChannels negative = chooseVectorChannels(channels, "-grad(temp)");
  EXPECT_EQ(negative.name, "-grad(temp)");
  EXPECT_EQ(negative.channels[2], "-d(temp)/dz");
  EXPECT_EQ(negative.gradientSign, -1.0f);
  // A name with parentheses is taken whole.
  EXPECT_EQ(chooseVectorChannels(channels, "grad(Y(H2))").gradientOf, "Y(H2)");
  // Point data "all" keeps the scalar: it is no component of the vector.
  EXPECT_EQ(choosePointData(channels, gradient, "all"),
            (std::vector<std::string>{"temp", "Y(H2)"}));
}

TEST(GradientVector, OfAMissingChannelIsRefusedNamingTheSettingAndTheChannels) {
  const ChannelCatalog channels = catalogNamed({"temp", "dens", "velx", "vely", "velz"});
  EXPECT_EQ(testing::inputErrorOf([&] { chooseVectorChannels(channels, "grad(tmp)"); }),
            "--vector: no channel 'tmp' in test-data to take the gradient of (did you mean "
            "'temp'?); the channels are: temp, dens, velx, vely, velz");
  EXPECT_THAT(testing::inputErrorOf([&] { chooseVectorChannels(channels, "-grad(pressure)"); }),
              HasSubstr("--vector: no channel 'pressure' in test-data"));
}

TEST(GradientVector, MalformedRequestsAreRefusedNamingTheSetting) {
  const ChannelCatalog channels = catalogNamed({"temp"});
  for (const char* request : {"grad(", "grad()", "-grad(temp", "grad(temp)x", "-grad()"}) {
    SCOPED_TRACE(request);
    EXPECT_EQ(testing::inputErrorOf([&] { chooseVectorChannels(channels, request); }),
              std::string("--vector: '") + request +
                  "' is not grad(NAME) or -grad(NAME) with NAME a scalar channel (nor three "
                  "channels a,b,c)");
  }
  // Three channels and the default are as they were.
  EXPECT_THAT(testing::inputErrorOf([&] { chooseVectorChannels(channels, "gradient"); }),
              HasSubstr("must name exactly three channels"));
}

// A gradient beyond float32's reach for the tracer is refused naming the scalar.
TEST(GradientVector, TooSteepForFloatArithmeticIsRefused) {
  const bricks::AmrField field = linearScalar(6, glm::dvec3(1e20), glm::dvec3(1.0));
  EXPECT_THAT(testing::inputErrorOf(
                  [&] { buildVectorVolume(field, chooseVectorChannels(field, "grad(f)")); }),
              HasSubstr("the gradient of 'f' is"));
}

}  // namespace
}  // namespace amrstream::flow
