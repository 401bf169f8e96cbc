#include "render/camera.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <vector>

#include "glm_pixel.hpp"
#include "render/side_on_view.hpp"

namespace amrstream::render {
namespace {

using testing::glmPixel;

struct RandomView {
  OrbitCamera camera;
  float width, height;
};

RandomView randomView(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  RandomView v;
  v.camera.azimuthDegrees = 360.0f * unit(random);
  v.camera.elevationDegrees = -80.0f + 160.0f * unit(random);  // glm::lookAt fails at +-90
  v.camera.fovYDegrees = 10.0f + 80.0f * unit(random);
  v.camera.up = {int(random() % 3), random() % 2 ? 1.0f : -1.0f};
  v.camera.projection = random() % 2 ? Projection::Perspective : Projection::Orthographic;
  v.width = float(64 + random() % 1900);
  v.height = float(64 + random() % 1100);
  return v;
}

TEST(CameraFraming, EveryPointOfRandomTraceSetsIsInTheImage) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int set = 0; set < 200; ++set) {
    // A cluster of "trace points" somewhere in a 1000-cell domain, thin or round.
    const glm::vec3 centre = 1000.0f * glm::vec3(unit(random), unit(random), unit(random));
    const glm::vec3 spread =
        glm::vec3(unit(random), unit(random), unit(random)) * (1.0f + 300.0f * unit(random));
    std::vector<glm::vec3> points;
    glm::vec3 lower(INFINITY), upper(-INFINITY);
    for (int i = 0; i < 200; ++i) {
      const glm::vec3 p =
          centre + spread * (2.0f * glm::vec3(unit(random), unit(random), unit(random)) - 1.0f);
      points.push_back(p);
      lower = glm::min(lower, p), upper = glm::max(upper, p);
    }
    const RandomView v = randomView(random);
    const OrbitCamera framed = frameBox(v.camera, lower, upper, v.width / v.height);
    for (const glm::vec3& p : points) {
      const glm::vec2 pixel = glmPixel(framed, v.width, v.height, p);
      ASSERT_GE(pixel.x, 0.0f) << "set " << set;
      ASSERT_LE(pixel.x, v.width) << "set " << set;
      ASSERT_GE(pixel.y, 0.0f) << "set " << set;
      ASSERT_LE(pixel.y, v.height) << "set " << set;
    }
    // Framed tightly, not lost in the middle: a corner of the box comes within 3 % of the
    // image's side to an edge.
    float nearestEdge = INFINITY;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p((corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                        (corner & 4) ? upper.z : lower.z);
      const glm::vec2 f = glmPixel(framed, v.width, v.height, p) / glm::vec2(v.width, v.height);
      nearestEdge = std::min({nearestEdge, f.x, 1.0f - f.x, f.y, 1.0f - f.y});
    }
    EXPECT_GE(nearestEdge, 0.0f) << "set " << set;
    EXPECT_LT(nearestEdge, 0.03f) << "set " << set;
  }
}

TEST(CameraFraming, ProjectToImageAgreesWithGlm) {
  std::mt19937 random(5);
  std::uniform_real_distribution<float> unit(-50.0f, 50.0f);
  for (int i = 0; i < 500; ++i) {
    RandomView v = randomView(random);
    v.camera.target = glm::vec3(unit(random), unit(random), unit(random));
    v.camera.distance = 400.0f + 2.0f * unit(random);  // every point in front
    const glm::vec3 p(unit(random), unit(random), unit(random));
    const std::optional<glm::vec2> ours = projectToImage(v.camera, v.width, v.height, p);
    ASSERT_TRUE(ours.has_value());
    const glm::vec2 expected = glmPixel(v.camera, v.width, v.height, p);
    EXPECT_NEAR(ours->x, expected.x, 1e-3f * v.width) << i;
    EXPECT_NEAR(ours->y, expected.y, 1e-3f * v.height) << i;
  }
}

TEST(CameraFraming, ALookAtPointOffCentreStillShowsTheBox) {
  const glm::vec3 lower(0.0f), upper(100.0f, 40.0f, 10.0f);
  OrbitCamera camera;
  const OrbitCamera framed = frameBox(camera, lower, upper, 1.5f, 1.0f, glm::vec3(90, 35, 0));
  EXPECT_EQ(framed.target, glm::vec3(90, 35, 0));
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p((corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                      (corner & 4) ? upper.z : lower.z);
    const glm::vec2 pixel = glmPixel(framed, 300.0f, 200.0f, p);
    EXPECT_TRUE(pixel.x >= 0 && pixel.x <= 300 && pixel.y >= 0 && pixel.y <= 200) << corner;
  }
}

TEST(CameraViews, NamedViewsLookFromTheirAxis) {
  for (const char* name : {"+x", "-x", "+y", "-y", "+z", "-z"}) {
    for (const char* upName : {"+z", "+y", "-x"}) {
      const Axis up = *parseAxis(upName);
      const std::optional<NamedView> view = namedView(name, up);
      ASSERT_TRUE(view) << name;
      OrbitCamera camera;
      camera.up = up;
      camera.azimuthDegrees = view->azimuthDegrees;
      camera.elevationDegrees = view->elevationDegrees;
      const CameraFrame frame = cameraFrame(camera);
      const glm::vec3 from = parseAxis(name)->vector();
      EXPECT_NEAR(glm::dot(-frame.forward, from), 1.0f, 1e-5f) << name << " up " << upName;
      // A right-handed screen frame: right x up = backwards.
      EXPECT_NEAR(glm::length(glm::cross(frame.right, frame.up) + frame.forward), 0.0f, 1e-5f);
      if (from != up.vector() && from != -up.vector()) {
        EXPECT_NEAR(glm::dot(frame.up, up.vector()), 1.0f, 1e-5f) << name << " up " << upName;
      } else {  // along the up axis: the first axis after it points right
        glm::vec3 first(0.0f);
        first[(up.index + 1) % 3] = 1.0f;
        EXPECT_NEAR(glm::dot(frame.right, first), 1.0f, 1e-5f) << name << " up " << upName;
      }
    }
  }
  const std::optional<NamedView> iso = namedView("iso", Axis{});
  ASSERT_TRUE(iso);
  OrbitCamera camera;
  camera.azimuthDegrees = iso->azimuthDegrees;
  camera.elevationDegrees = iso->elevationDegrees;
  const glm::vec3 f = cameraFrame(camera).forward;
  EXPECT_NEAR(std::abs(f.x), std::abs(f.y), 1e-5f);
  EXPECT_NEAR(std::abs(f.x), std::abs(f.z), 1e-5f);
  EXPECT_FALSE(namedView("front", Axis{}));
  EXPECT_FALSE(parseAxis("+w"));
}

TEST(CameraViews, OrthographicSizesDoNotShrinkWithDepth) {
  OrbitCamera camera;
  camera.projection = Projection::Orthographic;
  camera.azimuthDegrees = 0.0f, camera.elevationDegrees = 0.0f;  // looking along -x
  camera.distance = 50.0f;
  const auto width = [&](float x) {
    return projectToImage(camera, 200, 200, {x, 5, 0})->x -
           projectToImage(camera, 200, 200, {x, -5, 0})->x;
  };
  EXPECT_NEAR(width(-40.0f), width(40.0f), 1e-3f);
  camera.projection = Projection::Perspective;
  EXPECT_GT(width(40.0f), 1.5f * width(-40.0f));  // nearer, larger
}

// Lines running one way that the default view looks along are seen across; lines in the plane
// across the up axis from above; lines every way keep the default direction.
TEST(SideOnView, LooksAcrossTheLinesRatherThanAlongThem) {
  const auto along = [](glm::vec3 direction, int count) {
    std::vector<shared::TubeSegment> segments;
    for (int i = 0; i < count; ++i) {
      const glm::vec3 start(float(i % 7), float(i % 5), float(i % 3));
      segments.push_back({start, 0.0f, start + direction, 0.0f});
    }
    return segments;
  };
  OrbitCamera camera;  // azimuth 35, elevation 25, up +z
  for (const glm::vec3 direction :
       {glm::vec3(1, 0, 0.3f), glm::vec3(1, 0.7f, 0.6f), glm::vec3(1, 1, 0.3f)}) {
    const std::vector<shared::TubeSegment> bundle = along(direction, 50);
    const OrbitCamera side = sideOn(camera, bundle);
    EXPECT_LT(lengthAlong(bundle, cameraFrame(side).forward), kSideOnSlack + 0.01f)
        << direction.x << direction.y;
    EXPECT_EQ(side.elevationDegrees, 25.0f);
  }
  std::vector<shared::TubeSegment> plane = along({1, 0, 0}, 20);
  const std::vector<shared::TubeSegment> other = along({0.3f, 1, 0}, 20);
  plane.insert(plane.end(), other.begin(), other.end());
  const CameraFrame above = cameraFrame(sideOn(camera, plane));
  EXPECT_NEAR(above.forward.z, -1.0f, 1e-5f);
  EXPECT_NEAR(above.right.x, 1.0f, 1e-5f);  // x right, y up
  // Staircases in the plane, as much along x as along y: no side view gains on the default,
  // yet they lie across the up axis.
  std::vector<shared::TubeSegment> stairs = along({1, 0, 0}, 20);
  const std::vector<shared::TubeSegment> risers = along({0, 1, 0}, 20);
  stairs.insert(stairs.end(), risers.begin(), risers.end());
  EXPECT_NEAR(cameraFrame(sideOn(camera, stairs)).forward.z, -1.0f, 1e-5f);
  std::vector<shared::TubeSegment> everyWay = along({1, 0, 0}, 10);
  for (const glm::vec3 d : {glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)}) {
    const std::vector<shared::TubeSegment> more = along(d, 10);
    everyWay.insert(everyWay.end(), more.begin(), more.end());
  }
  EXPECT_EQ(sideOn(camera, everyWay), camera);
  EXPECT_EQ(sideOn(camera, {}), camera);
}

}  // namespace
}  // namespace amrstream::render
