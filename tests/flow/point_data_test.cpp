// Point data along the traces: channels reconstructed with the tent method at every point, and
// the vorticity (curl of the reconstruction), against exact answers.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "flow/cpu_tracer.hpp"
#include "flow/sampler.hpp"
#include "flow_test_support.hpp"
#include "volume_options.hpp"

namespace amrstream::flow {
namespace {

// The vector (vx, vy, vz) plus the scalars "lin" = 2x - y + 3z + 1 and "ones" = 1 on a layout.
bricks::AmrField withScalars(const bricks::AmrField& cells) {
  std::vector<Channel> channels = cells.channels();
  Channel lin{"lin", {}}, ones{"ones", {}};
  for (std::size_t i = 0; i < cells.cellCount(); ++i) {
    const double w = bricks::AmrField::cellWidth(cells.levels()[i]);
    const glm::dvec3 c = glm::dvec3(cells.lowers()[i]) + 0.5 * w;
    lin.values.push_back(float(2.0 * c.x - c.y + 3.0 * c.z + 1.0));
    ones.values.push_back(1.0f);
  }
  channels.push_back(lin);
  channels.push_back(ones);
  return bricks::AmrField({cells.lowers().begin(), cells.lowers().end()},
                          {cells.levels().begin(), cells.levels().end()}, channels,
                          cells.transform(), "with scalars");
}

TEST(PointData, ChannelsUseTheVectorsWeights) {
  // A channel equal to the vector's x component is reconstructed with the same weights in the
  // same order: at every point it equals the sampled vector's x exactly, on any layout.
  testing::RandomAmrOptions layout;
  layout.levels = 4;
  const bricks::AmrField field = withScalars(testing::randomAmr(7, layout, [](glm::dvec3 p) {
    return glm::vec3(0.2 + 0.01 * p.y, 0.1 * std::cos(0.2 * p.x), 0.05);
  }));
  const VectorVolume volume =
      buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"}, testing::withPointData({"ones", "vx"}));
  TraceOptions options;
  options.maxSteps = 200;
  std::vector<glm::dvec3> seeds;
  for (int i = 0; i < 20; ++i) seeds.push_back({1.0 + 0.5 * i, 1.5 + 0.4 * i, 3.0});
  const TraceSet t = traceStreamlines(volume, seeds, options);
  ASSERT_EQ(t.channelNames, (std::vector<std::string>{"ones", "vx"}));
  ASSERT_EQ(t.channels.size(), 2 * t.pointCount());
  EXPECT_GT(t.pointCount(), 1000u);
  for (std::uint64_t i = 0; i < t.pointCount(); ++i) {
    ASSERT_NEAR(t.channels[2 * i], 1.0f, 1e-6f) << "point " << i;
    ASSERT_EQ(t.channels[2 * i + 1], t.vectors[i].x) << "point " << i;
  }
}

TEST(PointData, ALinearChannelIsExactInsideOneLevel) {
  testing::RandomAmrOptions layout;
  layout.levels = 1;
  layout.rootCells = glm::ivec3(16, 16, 16);
  const bricks::AmrField field =
      withScalars(testing::randomAmr(0, layout, [](auto) { return glm::vec3(0.3f, 0.2f, 0.1f); }));
  const VectorVolume volume =
      buildVectorVolume(field, {{"vx", "vy", "vz"}, "v"}, testing::withPointData({"lin"}));
  TraceOptions options;
  options.maxSteps = 40;
  const std::vector<glm::dvec3> seeds{{4.0, 5.0, 6.0}, {8.2, 7.1, 5.5}};
  const TraceSet t = traceStreamlines(volume, seeds, options);
  for (std::uint64_t i = 0; i < t.pointCount(); ++i) {
    const glm::dvec3 p(t.positions[i]);
    ASSERT_NEAR(t.channels[i], 2.0 * p.x - p.y + 3.0 * p.z + 1.0, 1e-4) << "point " << i;
  }
}

TEST(PointData, VorticityOfSolidBodyRotationIsTwiceTheAngularVelocity) {
  // v = omega x r + (0, 0, c): curl v = (0, 0, 2 omega) everywhere; with a physical transform
  // (finest cell 0.5 wide) the derivatives are per physical length.
  const double omega = 0.1;
  testing::RandomAmrOptions layout;
  layout.levels = 1;
  layout.rootCells = glm::ivec3(16, 16, 8);
  const bricks::AmrField cells = testing::randomAmr(0, layout, [&](glm::dvec3 p) {
    const glm::dvec3 r = 0.5 * (p - glm::dvec3(8.0, 8.0, 0.0));  // physical offset from the axis
    return glm::vec3(-omega * r.y, omega * r.x, 0.05);
  });
  const bricks::AmrField field({cells.lowers().begin(), cells.lowers().end()},
                               {cells.levels().begin(), cells.levels().end()}, cells.channels(),
                               {{0.0, 0.0, 0.0}, {0.5, 0.5, 0.5}}, "scaled");
  const VectorVolume volume = testing::volumeOf(field);
  TraceOptions options;
  options.vorticity = true;
  options.maxSteps = 100;
  const std::vector<glm::dvec3> seeds{{5.0, 4.0, 1.0}, {2.0, 3.0, 2.0}};
  const TraceSet t = traceStreamlines(volume, seeds, options);
  ASSERT_EQ(t.vorticity.size(), t.pointCount());
  for (std::uint64_t i = 0; i < t.pointCount(); ++i) {
    ASSERT_NEAR(t.vorticity[i].x, 0.0f, 1e-5f);
    ASSERT_NEAR(t.vorticity[i].y, 0.0f, 1e-5f);
    ASSERT_NEAR(t.vorticity[i].z, 2.0 * omega, 1e-5) << "point " << i;
  }
}

TEST(PointData, VorticityMatchesCentralDifferencesOfTheSampler) {
  // On a multi-level layout the reconstruction is piecewise smooth: away from the kinks (cell
  // centre planes, brick and level boundaries), central differences of sampleVector approach its
  // curl. A point is compared only where one-sided differences on both sides agree.
  testing::RandomAmrOptions layout;
  layout.levels = 3;
  const VectorVolume volume = testing::volumeOf(testing::randomAmr(9, layout));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u(0.5f, 11.5f);
  int compared = 0;
  for (int k = 0; k < 600; ++k) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    const VectorSample s = sampleVector(volume, p);
    if (!s.valid) continue;
    const float h = 1e-2f;
    glm::dvec3 jacobian[3];
    bool smooth = true;
    for (int d = 0; d < 3; ++d) {
      glm::vec3 step(0.0f);
      step[d] = h;
      const glm::dvec3 here(s.value), ahead(sampleVector(volume, p + step).value),
          behind(sampleVector(volume, p - step).value);
      const glm::dvec3 right = (ahead - here) / double(h), left = (here - behind) / double(h);
      smooth = smooth && glm::length(right - left) < 1e-3;  // no kink within h
      jacobian[d] = 0.5 * (right + left);
    }
    if (!smooth) continue;
    const glm::dvec3 curl(jacobian[1].z - jacobian[2].y, jacobian[2].x - jacobian[0].z,
                          jacobian[0].y - jacobian[1].x);
    const glm::vec3 w = sampleVorticity(volume, s.region, p);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(w[c], curl[c], 2e-3) << "k " << k;
    ++compared;
  }
  EXPECT_GT(compared, 150);
}

}  // namespace
}  // namespace amrstream::flow
