// The slice's LIC on every backend (gpu::PlaneLic: the grid probe, then shaders/glsl/lic.comp)
// against the CPU's: slice::lineIntegralConvolution of slice::samplePixels's vectors at the same
// pixel centres, across an axis, off axis, and through a window that reaches past the domain.

#include <gtest/gtest.h>

#include <cmath>

#include "flow/uniform_resample.hpp"
#include "gpu/plane_lic.hpp"
#include "gpu_test.hpp"
#include "slice/lic.hpp"
#include "slice/plane_field.hpp"
#include "slice/slice_plane.hpp"
#include "synth/generators.hpp"

namespace amrstream::gpu {
namespace {

class GpuSliceLicTest : public testing::GpuTest, public ::testing::WithParamInterface<Backend> {
 protected:
  vk::CapabilitySet required() const override { return requiredCapabilities(GetParam()); }
};

flow::VectorVolume cloudVolume() {
  BuiltinOptions g;
  g.levels = 3;
  g.rootBlocks = 2;
  g.targetCells = 20000;
  return flow::buildVectorVolume(synth::generate("cloud", g),
                                 flow::VectorChannels{{"magx", "magy", "magz"}, "mag"}, {});
}

struct Comparison {
  std::size_t pixels = 0, withData = 0, equal = 0, close = 0;
  float largest = 0.0f;
};

Comparison compareLic(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume,
                      const slice::SliceRequest& request) {
  const slice::SlicePlane plane =
      slice::slicePlane(request, volume.transform.toPhysical(glm::dvec3(volume.domain.lower)),
                        volume.transform.toPhysical(glm::dvec3(volume.domain.upper)));
  slice::LicOptions options;
  options.halfLengthPixels = 6.0f;
  options.noiseSeed = 3;
  const std::vector<float> expected = slice::lineIntegralConvolution(
      slice::inPlaneImage(plane, slice::samplePixels(volume, slice::pixelGrid(volume, plane))),
      options);

  PlaneLic lic(ctx, backend, volume);
  const std::vector<float> got =
      lic.convolve(slice::pixelGrid(volume, plane), slice::licParams(plane, options));

  Comparison c;
  c.pixels = expected.size();
  EXPECT_EQ(got.size(), expected.size());
  for (std::size_t n = 0; n < std::min(got.size(), expected.size()); ++n) {
    EXPECT_EQ(std::isnan(got[n]), std::isnan(expected[n])) << "pixel " << n;
    if (std::isnan(expected[n]) || std::isnan(got[n])) continue;
    ++c.withData;
    const float difference = std::abs(got[n] - expected[n]);
    c.equal += difference == 0.0f;
    c.close += difference <= 1e-3f;
    c.largest = std::max(c.largest, difference);
  }
  return c;
}

void expectTwins(const Comparison& c) {
  EXPECT_GT(c.withData, c.pixels / 2);
  // On lavapipe, whose float arithmetic rounds as the CPU's does, every pixel is bit for bit the
  // CPU's. A GPU may divide and take square roots within a few units in the last place, so that a
  // streamline crosses into another pixel a step earlier or later now and then.
  EXPECT_GE(double(c.equal), 0.98 * double(c.withData)) << c.equal << " of " << c.withData;
  EXPECT_GE(double(c.close), 0.995 * double(c.withData)) << c.close << " of " << c.withData;
  EXPECT_LT(c.largest, 0.25f);
}

TEST_P(GpuSliceLicTest, EqualsTheCpusAcrossAnAxis) {
  const flow::VectorVolume volume = cloudVolume();
  slice::SliceRequest request;
  request.normal = "z";
  request.width = 96;
  expectTwins(compareLic(ctx(), GetParam(), volume, request));
  request.normal = "x";
  request.point = glm::dvec3(0.3, 0.5, 0.5);
  expectTwins(compareLic(ctx(), GetParam(), volume, request));
}

TEST_P(GpuSliceLicTest, EqualsTheCpusOffAxisAndPastTheDomain) {
  const flow::VectorVolume volume = cloudVolume();
  slice::SliceRequest request;
  request.normal = "1,2,3";
  request.width = 80;
  expectTwins(compareLic(ctx(), GetParam(), volume, request));
  request.normal = "y";
  request.window = std::array<double, 4>{-0.2, 0.1, 0.7, 1.3};
  const Comparison c = compareLic(ctx(), GetParam(), volume, request);
  expectTwins(c);
  EXPECT_LT(c.withData, c.pixels);  // part of the window has no data
}

INSTANTIATE_TEST_SUITE_P(Backends, GpuSliceLicTest,
                         ::testing::Values(Backend::RayQuery, Backend::Pipeline, Backend::Compute),
                         [](const auto& info) { return std::string(backendName(info.param)); });

}  // namespace
}  // namespace amrstream::gpu
