// The context volume with the linear interpolant on every backend. Oracle: a scalar that is
// linear in y and z, seen along x from far away with a narrow field of view, is nearly constant
// along each ray, so a pixel is the continuous emission-absorption integral of the analytic
// scalar along its ray, whatever the march's step. The linear interpolant must reproduce it on a
// random 4-level layout to 8-bit rounding; the tent, whose errors sit at the level boundaries,
// is measured beside it to show that the check can fail.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flow/vector_volume.hpp"
#include "gpu_test.hpp"
#include "random_amr.hpp"
#include "render/tube_renderer.hpp"

namespace amrstream::render {
namespace {

constexpr float kVolumeMax = 1.2f;
constexpr float kOpacity = 0.06f;

double scalarAt(glm::dvec3 p) { return 0.15 + 0.03 * p.y + 0.012 * p.z; }

// The renderer's transfer function (render_frame.glsl) on x in [0, 1].
glm::dvec3 transferColour(double x) {
  return glm::mix(glm::dvec3(0.20, 0.30, 0.55), glm::dvec3(1.0, 0.88, 0.70), x);
}

// Premultiplied colour of the continuous emission-absorption integral along o + t d, t in
// [t0, t1], by fine midpoint quadrature of the analytic scalar.
glm::dvec3 volumeIntegral(glm::dvec3 o, glm::dvec3 d, double t0, double t1) {
  constexpr int kSteps = 4000;
  const double dt = (t1 - t0) / kSteps;
  glm::dvec3 colour(0.0);
  double transmittance = 1.0;
  for (int i = 0; i < kSteps; ++i) {
    const double x = std::clamp(scalarAt(o + (t0 + (i + 0.5) * dt) * d) / kVolumeMax, 0.0, 1.0);
    const double alpha = 1.0 - std::exp(-kOpacity * x * x * dt);
    colour += transmittance * alpha * transferColour(x);
    transmittance *= 1.0 - alpha;
  }
  return colour;
}

struct PixelErrors {
  int largest = 0;  // in 8-bit levels
  int compared = 0;
};

class LinearVolumeTest : public testing::GpuTest,
                         public ::testing::WithParamInterface<gpu::Backend> {
 protected:
  vk::CapabilitySet required() const override { return gpu::requiredCapabilities(GetParam()); }

  // Renders one frame of the volume of "vx" and compares every pixel whose ray crosses the
  // domain well inside its y and z faces with the oracle.
  PixelErrors renderAndCompare(flow::Interpolant interpolant) {
    flow::VolumeOptions options;
    options.interpolant = interpolant;
    const flow::VectorVolume volume =
        flow::buildVectorVolume(field_, {{"vx", "vy", "vz"}, "v"}, options);
    const std::vector<float> scalars = flow::gatherScalar(field_, volume, "vx");
    TubeRenderer renderer(ctx(), GetParam(), volume, scalars);
    constexpr std::uint32_t kSize = 64;
    renderer.resize(kSize, kSize);
    RenderSettings settings;
    settings.ambientOcclusion = false;
    settings.volume = true;
    settings.logVolume = false;
    settings.volumeRange = {0.0f, kVolumeMax};
    settings.volumeOpacity = kOpacity;
    settings.volumeStepScale = 1.0f;
    settings.background = glm::vec3(0.0f);
    const glm::vec3 lower(volume.domain.lower), upper(volume.domain.upper);
    OrbitCamera camera;
    camera.target = 0.5f * (lower + upper);
    camera.azimuthDegrees = 0.0f;
    camera.elevationDegrees = 0.0f;
    camera.fovYDegrees = 4.0f;
    camera.distance = 0.55f * (upper.y - lower.y) / std::tan(glm::radians(2.0f));
    renderer.renderFrame(camera, settings);
    const Image image = renderer.readImage();

    const CameraFrame view = cameraFrame(camera);
    const float tanHalfFov = std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
    PixelErrors errors;
    for (std::uint32_t py = 0; py < kSize; ++py)
      for (std::uint32_t px = 0; px < kSize; ++px) {
        const glm::vec2 ndc = (glm::vec2(px, py) + 0.5f) / float(kSize) * 2.0f - 1.0f;
        const glm::dvec3 d = glm::normalize(glm::dvec3(
            view.forward + ndc.x * tanHalfFov * view.right - ndc.y * tanHalfFov * view.up));
        const glm::dvec3 o(view.eye);
        const double t0 = (double(upper.x) - o.x) / d.x, t1 = (double(lower.x) - o.x) / d.x;
        const glm::dvec3 in = o + t0 * d, out = o + t1 * d;
        const auto inside = [&](glm::dvec3 p) {
          return p.y > lower.y + 0.5 && p.y < upper.y - 0.5 && p.z > lower.z + 0.5 &&
                 p.z < upper.z - 0.5;
        };
        if (!inside(in) || !inside(out)) continue;
        const glm::dvec3 expected = glm::clamp(volumeIntegral(o, d, t0, t1), 0.0, 1.0);
        const std::size_t at = 4 * (std::size_t(py) * kSize + px);
        for (int c = 0; c < 3; ++c) {
          const int want = int(expected[c] * 255.0 + 0.5);
          errors.largest = std::max(errors.largest, std::abs(int(image.rgba[at + c]) - want));
        }
        ++errors.compared;
      }
    return errors;
  }

  bricks::AmrField field_ = testing::randomAmr(
      11, {.levels = 4, .rootCells = {3, 3, 3}, .refineProbability = 0.45, .origin = {0, 0, 0}},
      [](glm::dvec3 p) { return glm::vec3(scalarAt(p), 0.1, 0.2); });
};

TEST_P(LinearVolumeTest, ShowsALinearScalarAsItsAnalyticIntegral) {
  const PixelErrors linear = renderAndCompare(flow::Interpolant::Linear);
  const PixelErrors tent = renderAndCompare(flow::Interpolant::Tent);
  EXPECT_GT(linear.compared, 1500);
  EXPECT_LE(linear.largest, 1) << "the tent's largest error: " << tent.largest;
  EXPECT_GE(tent.largest, 4) << "the oracle should see the tent's errors at level boundaries";
  std::cout << "largest pixel error (8-bit levels) over " << linear.compared << " pixels: linear "
            << linear.largest << ", tent " << tent.largest << "\n";
}

std::string backendLabel(const ::testing::TestParamInfo<gpu::Backend>& info) {
  return std::string(gpu::backendName(info.param));
}

INSTANTIATE_TEST_SUITE_P(Backends, LinearVolumeTest,
                         ::testing::Values(gpu::Backend::RayQuery, gpu::Backend::Pipeline,
                                           gpu::Backend::Compute),
                         backendLabel);

}  // namespace
}  // namespace amrstream::render
