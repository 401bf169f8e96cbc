// The tube renderer on every backend the device supports: which pixels show a tube must agree
// with an independent ray-segment distance test, and a rendered scene (traces of the rotation
// field with ambient occlusion and the volume) must match the reference image in
// tests/render/reference within a tolerance.

#include "render/tube_renderer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <optional>
#include <random>

#include "flow/cpu_tracer.hpp"
#include "flow/seed_strategies.hpp"
#include "flow/seeds.hpp"
#include "gpu_test.hpp"
#include "render/image/colour_map.hpp"
#include "render/image/image_compare.hpp"
#include "render/image/png_io.hpp"
#include "synth/generators.hpp"

namespace amrstream::render {
namespace {

// The distance between the ray o + t d (t >= 0, d unit) and the segment [a, b]. The distance of
// a point to the ray is a convex function of the point, so along the segment it is convex in the
// segment parameter: a ternary search finds its minimum. Independent of the shaders' quadratics.
double raySegmentDistance(glm::dvec3 o, glm::dvec3 d, glm::dvec3 a, glm::dvec3 b) {
  const auto toRay = [&](double s) {
    const glm::dvec3 p = a + s * (b - a);
    const double t = std::max(0.0, glm::dot(p - o, d));
    return glm::length(o + t * d - p);
  };
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (toRay(m1) < toRay(m2))
      hi = m2;
    else
      lo = m1;
  }
  return std::min({toRay(0.0), toRay(1.0), toRay(0.5 * (lo + hi))});
}

OrbitCamera looking(float azimuthDegrees, float elevationDegrees,
                    Projection projection = Projection::Perspective) {
  OrbitCamera camera;
  camera.azimuthDegrees = azimuthDegrees;
  camera.elevationDegrees = elevationDegrees;
  camera.projection = projection;
  return camera;
}

class TubeRendererTest : public testing::GpuTest,
                         public ::testing::WithParamInterface<gpu::Backend> {
 protected:
  vk::CapabilitySet required() const override { return gpu::requiredCapabilities(GetParam()); }

  // A 32^3 rotation dataset: its volume gives the renderer a domain and regions.
  flow::VectorVolume smallVolume() {
    field_ = synth::generate("rotation", {.levels = 2, .rootBlocks = 2, .targetCells = 20000});
    return flow::buildVectorVolume(*field_, flow::chooseVectorChannels(*field_, ""));
  }

  static constexpr std::uint32_t kWidth = 96, kHeight = 72;

  // `count` segments from random points of the box [lower, lower + extent] by up to step / 2 on
  // each axis; every `spheresEvery`-th one (0: none) a sphere.
  static std::vector<shared::TubeSegment> randomSegments(glm::vec3 lower, glm::vec3 extent,
                                                         int count, float step, unsigned seed,
                                                         int spheresEvery) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const auto point = [&] { return glm::vec3(unit(random), unit(random), unit(random)); };
    std::vector<shared::TubeSegment> segments;
    for (int i = 0; i < count; ++i) {
      const glm::vec3 a = lower + extent * point();
      const glm::vec3 b = a + step * (point() - 0.5f);
      segments.push_back({a, 0.0f, spheresEvery > 0 && i % spheresEvery == 0 ? a : b, 1.0f});
    }
    return segments;
  }

  struct PixelCheck {
    std::size_t tubePixels = 0, mismatches = 0, ambiguous = 0;
  };

  // Renders the segments as red tubes without occlusion (frame 0: one ray through each pixel's
  // centre) and compares every pixel with the ray-segment distance; pixels whose distance is
  // within `edge` radii of the radius count as ambiguous. Orthographic oracle rays start on a
  // plane behind every segment, as tall as the view at the target.
  // With `leastFraction` below 1, radii follow the segments' values over [0, 1]
  // (segmentRadius); `oracleLeastFraction` is the oracle's (the same unless a test shows that a
  // wrong one fails).
  PixelCheck checkTubePixels(const flow::VectorVolume& volume,
                             const std::vector<shared::TubeSegment>& segments, float radius,
                             const OrbitCamera& camera, double edge, float leastFraction = 1.0f,
                             std::optional<float> oracleLeastFraction = std::nullopt) {
    TubeRenderer renderer(ctx(), GetParam(), volume, {});
    renderer.setTubes(segments, radius);
    const std::array<glm::vec3, 2> red{glm::vec3(1, 0, 0), glm::vec3(1, 0, 0)};
    renderer.setColourMap(red);
    renderer.resize(kWidth, kHeight);
    RenderSettings settings;
    settings.tubeRadius = radius;
    settings.ambientOcclusion = false;
    settings.colourRange = {0.0f, 1.0f};
    settings.leastRadiusFraction = leastFraction;
    renderer.renderFrame(camera, settings);
    std::vector<double> radii;
    for (const auto& s : segments)
      radii.push_back(segmentRadius(s, radius, oracleLeastFraction.value_or(leastFraction),
                                    settings.colourRange));
    const Image image = renderer.readImage();

    const bool perspective = camera.projection == Projection::Perspective;
    const CameraFrame view = cameraFrame(camera);
    const double tanHalf = std::tan(glm::radians(double(camera.fovYDegrees)) / 2);
    const double halfHeight = perspective ? tanHalf : tanHalf * camera.distance;
    const glm::dvec3 behind = glm::dvec3(camera.target) - 1000.0 * glm::dvec3(view.forward);
    PixelCheck check;
    for (std::uint32_t y = 0; y < kHeight; ++y)
      for (std::uint32_t x = 0; x < kWidth; ++x) {
        const glm::dvec2 ndc = (glm::dvec2(x, y) + 0.5) / glm::dvec2(kWidth, kHeight) * 2.0 - 1.0;
        const glm::dvec3 offset =
            ndc.x * double(kWidth) / kHeight * halfHeight * glm::dvec3(view.right) -
            ndc.y * halfHeight * glm::dvec3(view.up);
        const glm::dvec3 d = perspective ? glm::normalize(glm::dvec3(view.forward) + offset)
                                         : glm::dvec3(view.forward);
        const glm::dvec3 o = perspective ? glm::dvec3(view.eye) : behind + offset;
        // The ray's distance to the nearest capsule surface, in that capsule's radii.
        double margin = 1e300;
        for (std::size_t i = 0; i < segments.size(); ++i)
          margin = std::min(
              margin, raySegmentDistance(o, d, segments[i].a, segments[i].b) / radii[i] - 1.0);
        if (std::abs(margin) < edge) {
          ++check.ambiguous;
          continue;
        }
        const Rgba8 c = image.at(x, y);
        const bool hit = margin<0.0, shown = c.r> 50 && c.r > c.b + 30;
        check.tubePixels += hit;
        check.mismatches += hit != shown;
      }
    return check;
  }

  std::optional<bricks::AmrField> field_;
};

TEST_P(TubeRendererTest, TubePixelsMatchAnIndependentRaySegmentTest) {
  const flow::VectorVolume volume = smallVolume();
  const glm::vec3 lower(volume.domain.lower), upper(volume.domain.upper);
  // Some are spheres (a == b).
  const std::vector<shared::TubeSegment> segments =
      randomSegments(lower, upper - lower, 120, 3.0f, 7, 10);
  for (const Projection projection : {Projection::Perspective, Projection::Orthographic}) {
    const OrbitCamera camera =
        frameBox(looking(30.0f, 20.0f, projection), lower, upper, float(kWidth) / kHeight, 1.6f);
    const PixelCheck check = checkTubePixels(volume, segments, 0.4f, camera, 0.02);
    EXPECT_GT(check.tubePixels, kWidth * kHeight / 50)
        << "the scene should cover a fair part of the image";
    EXPECT_EQ(check.mismatches, 0u)
        << "of " << kWidth * kHeight << " pixels (" << check.ambiguous
        << " on tube edges skipped), "
        << (projection == Projection::Perspective ? "perspective" : "orthographic");
  }
}

// Radii that follow the colour field: each capsule as thick as its segment's mean value says,
// from a quarter of the radius at the range's low end to all of it at the high end; the oracle
// with one radius for all disagrees.
TEST_P(TubeRendererTest, TubeRadiiFollowTheColourFieldWhenAsked) {
  const flow::VectorVolume volume = smallVolume();
  const glm::vec3 lower(volume.domain.lower), upper(volume.domain.upper);
  std::vector<shared::TubeSegment> segments =
      randomSegments(lower, upper - lower, 120, 3.0f, 11, 10);
  std::mt19937 random(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (shared::TubeSegment& s : segments) {
    s.valueA = unit(random);
    s.valueB = unit(random);
  }
  const OrbitCamera camera =
      frameBox(looking(30.0f, 20.0f), lower, upper, float(kWidth) / kHeight, 1.6f);
  const PixelCheck check = checkTubePixels(volume, segments, 0.8f, camera, 0.03, 0.25f);
  EXPECT_GT(check.tubePixels, kWidth * kHeight / 80);
  EXPECT_EQ(check.mismatches, 0u) << "of " << check.tubePixels << " tube pixels";
  const PixelCheck oneRadius = checkTubePixels(volume, segments, 0.8f, camera, 0.03, 0.25f, 1.0f);
  EXPECT_GT(oneRadius.mismatches, check.tubePixels / 10)
      << "one radius for every tube should not match";
}

// Thin tubes in the far corner of a deep domain (a 12-level nest, 16,384 finest cells
// across), seen in an orthographic view framed on them: parallel rays must start near the tubes,
// or float rounding in the capsule test loses them (it did when they started outside the domain).
TEST_P(TubeRendererTest, ThinTubesInADeepDomainShowInOrthographicViews) {
  field_ = synth::generate("nest", {.levels = 12});
  const flow::VectorVolume volume =
      flow::buildVectorVolume(*field_, flow::chooseVectorChannels(*field_, ""));
  ASSERT_GT(volume.domain.upper.x - volume.domain.lower.x, 8000) << "not a deep domain";
  // The corner away from the eye (azimuth 30, elevation 20 looks from +x, +y, +z).
  const glm::vec3 corner = glm::vec3(volume.domain.lower) + 20.0f;
  const std::vector<shared::TubeSegment> segments =
      randomSegments(corner, glm::vec3(20.0f), 60, 4.0f, 3, 0);
  const OrbitCamera camera = frameBox(looking(30.0f, 20.0f, Projection::Orthographic), corner,
                                      corner + 20.0f, float(kWidth) / kHeight);
  const PixelCheck check = checkTubePixels(volume, segments, 0.15f, camera, 0.05);
  EXPECT_GT(check.tubePixels, 30u);
  EXPECT_EQ(check.mismatches, 0u) << "of " << check.tubePixels << " tube pixels";
}

// Traces of the rotation field (circles about the z axis) as tubes with ambient occlusion, in
// front of the speed as a volume: the scene the reference image shows. Set
// AMRSTREAM_UPDATE_RENDER_REFERENCE=1 to rewrite the reference (then look at it before committing).
TEST_P(TubeRendererTest, MatchesTheReferenceImage) {
  const flow::VectorVolume volume = smallVolume();
  const flow::SeedList seeds =
      flow::seedsAlongLine(glm::dvec3(0.55, 0.5, 0.3), glm::dvec3(0.95, 0.5, 0.7), 12);
  flow::TraceOptions options;
  options.maxSteps = 120;
  const flow::TraceSet traces = flow::traceStreamlines(volume, seeds.points, options);
  ChannelValues unused;
  const ColourField colour = colourFieldOf(traces, "speed", *field_, volume, unused);
  const std::vector<float> speed = flow::gatherScalar(*field_, volume, "velx");

  TubeRenderer renderer(ctx(), GetParam(), volume, speed);
  RenderSettings settings;
  settings.tubeRadius = 0.6f;
  settings.aoSamples = 4;
  settings.aoDistance = 5.0f;
  settings.colourRange = rangeOf(colour.values);
  settings.volume = true;
  settings.logVolume = false;
  settings.volumeRange = {0.0f, 1.0f};
  settings.volumeOpacity = 0.03f;
  renderer.setTubes(buildTubeSegments(traces, colour, volume.transform), settings.tubeRadius);
  renderer.setColourMap(colourMapTable(ColourMap::Viridis));
  renderer.resize(128, 128);
  const OrbitCamera camera = frameBox(looking(20.0f, 35.0f), glm::vec3(volume.domain.lower),
                                      glm::vec3(volume.domain.upper), 1.0f, 1.3f);
  for (int frame = 0; frame < 8; ++frame) renderer.renderFrame(camera, settings);
  EXPECT_EQ(renderer.framesAccumulated(), 8u);
  const Image image = renderer.readImage();

  // The source tree's reference, unless AMRSTREAM_RENDER_REFERENCE_DIR names another copy (a
  // GPU machine running a carried build).
  const char* directory = std::getenv("AMRSTREAM_RENDER_REFERENCE_DIR");
  const std::filesystem::path reference =
      std::filesystem::path(directory ? directory : AMRSTREAM_RENDER_REFERENCE_DIR) /
      "rotation_tubes.png";
  if (const char* update = std::getenv("AMRSTREAM_UPDATE_RENDER_REFERENCE");
      update && *update == '1') {
    writePng(reference, image);
    GTEST_SKIP() << "wrote " << reference;
  }
  const ImageDifference difference = compareImages(image, readPng(reference), 24);
  EXPECT_LT(difference.meanAbsolute, 1.5);
  EXPECT_LT(difference.fractionAbove, 0.01) << "max difference " << int(difference.maxAbsolute);
  const ImageContent content = describeContent(image);
  EXPECT_GT(content.distinctColours, 500u);
  EXPECT_GT(content.fractionNotBackground, 0.1);
}

TEST_P(TubeRendererTest, StillFramesAccumulateAndAMovedCameraStartsAgain) {
  const flow::VectorVolume volume = smallVolume();
  TubeRenderer renderer(ctx(), GetParam(), volume, {});
  const std::vector<shared::TubeSegment> one{{glm::vec3(8), 0.0f, glm::vec3(24), 1.0f}};
  renderer.setTubes(one, 1.0f);
  renderer.resize(32, 32);
  RenderSettings settings;
  settings.tubeRadius = 1.0f;
  OrbitCamera camera = frameBox(OrbitCamera{}, glm::vec3(0), glm::vec3(32), 1.0f);
  renderer.renderFrame(camera, settings);
  renderer.renderFrame(camera, settings);
  EXPECT_EQ(renderer.framesAccumulated(), 2u);
  orbit(camera, 10.0f, 0.0f);
  renderer.renderFrame(camera, settings);
  EXPECT_EQ(renderer.framesAccumulated(), 1u);
  settings.tubeRadius = 2.0f;
  EXPECT_THROW(renderer.renderFrame(camera, settings), std::invalid_argument);
  settings.tubeRadius = 1.0f;
  settings.volume = true;
  EXPECT_THROW(renderer.renderFrame(camera, settings), std::invalid_argument);
}

// `count` segments of a helix about the volume's axis (x = y = 16): `turn` radians and `rise` up
// a segment, coloured from 0 to 1 along it.
std::vector<shared::TubeSegment> helix(int count, float turn, float radius, float z0, float rise) {
  std::vector<shared::TubeSegment> segments;
  const auto at = [&](int i) {
    const float t = turn * float(i);
    return glm::vec3(16.0f + radius * std::cos(t), 16.0f + radius * std::sin(t), z0 + rise * i);
  };
  for (int i = 0; i < count; ++i)
    segments.push_back({at(i), float(i) / float(count), at(i + 1), float(i + 1) / float(count)});
  return segments;
}

// Tubes appended ten at a time (36 times, their structures merging as they go), and the same
// made into one structure afterwards, render as the tubes set at once, pixel for pixel.
TEST_P(TubeRendererTest, AppendedTubesRenderAsTheSameTubesSetAtOnce) {
  const flow::VectorVolume volume = smallVolume();
  const std::vector<shared::TubeSegment> all = helix(360, 0.05f, 10.0f, 4.0f, 0.07f);
  const auto render = [&](const std::function<void(TubeRenderer&)>& set) {
    TubeRenderer renderer(ctx(), GetParam(), volume, {});
    set(renderer);
    const std::array<glm::vec3, 2> map{glm::vec3(0, 0, 1), glm::vec3(1, 0.5, 0)};
    renderer.setColourMap(map);
    renderer.resize(96, 64);
    RenderSettings settings;
    settings.tubeRadius = 0.6f;
    settings.ambientOcclusion = false;
    renderer.renderFrame(frameBox(OrbitCamera{}, glm::vec3(0), glm::vec3(32), 1.5f), settings);
    EXPECT_EQ(renderer.segmentCount(), all.size());
    return renderer.readImage();
  };
  const auto appendTenAtATime = [&](TubeRenderer& r) {
    r.setTubes(std::span(all).first(10), 0.6f);
    for (std::size_t n = 10; n < all.size(); n += 10)
      r.appendTubes(std::span(all).subspan(n, 10), std::span(all).first(n + 10), 0.6f);
  };
  const Image once = render([&](TubeRenderer& r) { r.setTubes(all, 0.6f); });
  const Image appended = render(appendTenAtATime);
  const Image consolidated = render([&](TubeRenderer& r) {
    appendTenAtATime(r);
    r.consolidateTubes();
    EXPECT_EQ(r.tubeStructures(), 1u);
  });
  // compute builds the one BVH on another thread, keeping its chunks until it is put in place.
  const Image inBackground = render([&](TubeRenderer& r) {
    appendTenAtATime(r);
    const std::size_t appendedStructures = r.tubeStructures();
    EXPECT_GT(appendedStructures, 1u);
    r.consolidateTubes(true);
    if (GetParam() == gpu::Backend::Compute) {
      EXPECT_EQ(r.tubeStructures(), appendedStructures);
    }
    r.finishConsolidation();
    EXPECT_EQ(r.tubeStructures(), 1u);
  });
  // Asked for at once while one is being built, the consolidation waits for that one.
  const Image thenAtOnce = render([&](TubeRenderer& r) {
    appendTenAtATime(r);
    r.consolidateTubes(true);
    r.consolidateTubes();
    EXPECT_EQ(r.tubeStructures(), 1u);
  });
  EXPECT_GT(describeContent(once).fractionNotBackground, 0.05);
  EXPECT_EQ(compareImages(appended, once, 0).maxAbsolute, 0);
  EXPECT_EQ(compareImages(consolidated, once, 0).maxAbsolute, 0);
  EXPECT_EQ(compareImages(inBackground, once, 0).maxAbsolute, 0);
  EXPECT_EQ(compareImages(thenAtOnce, once, 0).maxAbsolute, 0);
}

// A frame submitted without waiting renders the tubes as they stood: an append made meanwhile
// (compute grows its BVH on the host during the frame) shows in the next frame.
TEST_P(TubeRendererTest, AFrameInFlightShowsTheTubesBeforeAnAppend) {
  const flow::VectorVolume volume = smallVolume();
  const std::vector<shared::TubeSegment> all = helix(200, 0.08f, 9.0f, 6.0f, 0.1f);
  const std::array<glm::vec3, 2> map{glm::vec3(0, 0, 1), glm::vec3(1, 0.5, 0)};
  RenderSettings settings;
  settings.tubeRadius = 0.6f;
  settings.ambientOcclusion = false;
  const OrbitCamera camera = frameBox(OrbitCamera{}, glm::vec3(0), glm::vec3(32), 1.5f);
  const auto renderer = [&](std::span<const shared::TubeSegment> tubes) {
    auto r = std::make_unique<TubeRenderer>(ctx(), GetParam(), volume, std::span<const float>());
    r->setTubes(tubes, 0.6f);
    r->setColourMap(map);
    r->resize(96, 64);
    return r;
  };
  const std::span<const shared::TubeSegment> before = std::span(all).first(100);
  const Image expectedBefore = [&] {
    auto r = renderer(before);
    r->renderFrame(camera, settings);
    return r->readImage();
  }();
  const Image expectedAfter = [&] {
    auto r = renderer(all);
    r->renderFrame(camera, settings);
    return r->readImage();
  }();
  auto r = renderer(before);
  r->submitFrame(camera, settings);
  r->appendTubes(std::span(all).subspan(100), all, 0.6f);
  const Image inFlight = r->readImage();
  r->renderFrame(camera, settings);
  const Image next = r->readImage();
  EXPECT_GT(compareImages(expectedAfter, expectedBefore, 0).maxAbsolute, 0);
  EXPECT_EQ(compareImages(inFlight, expectedBefore, 0).maxAbsolute, 0);
  EXPECT_EQ(compareImages(next, expectedAfter, 0).maxAbsolute, 0);
}

std::string backendLabel(const ::testing::TestParamInfo<gpu::Backend>& info) {
  return std::string(gpu::backendName(info.param));
}

INSTANTIATE_TEST_SUITE_P(Backends, TubeRendererTest,
                         ::testing::Values(gpu::Backend::RayQuery, gpu::Backend::Pipeline,
                                           gpu::Backend::Compute),
                         backendLabel);

}  // namespace
}  // namespace amrstream::render
