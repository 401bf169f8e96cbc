#include "camera.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace amrstream::render {
namespace {

// The up axis and the two after it, a right-handed frame: first x second = up.
struct Basis {
  glm::vec3 up, first, second;
};

Basis basisOf(Axis up) {
  glm::vec3 first(0.0f);
  first[(up.index + 1) % 3] = 1.0f;
  const glm::vec3 u = up.vector();
  return {u, first, glm::cross(u, first)};
}

constexpr float kMargin = 1.04f;  // framed boxes keep this much room around them

}  // namespace

glm::vec3 Axis::vector() const {
  glm::vec3 v(0.0f);
  v[index] = sign;
  return v;
}

std::optional<Axis> parseAxis(std::string_view name) {
  float sign = 1.0f;
  if (!name.empty() && (name[0] == '+' || name[0] == '-')) {
    sign = name[0] == '-' ? -1.0f : 1.0f;
    name.remove_prefix(1);
  }
  if (name.size() != 1) return std::nullopt;
  const int index = name[0] == 'x' ? 0 : name[0] == 'y' ? 1 : name[0] == 'z' ? 2 : -1;
  if (index < 0) return std::nullopt;
  return Axis{index, sign};
}

CameraFrame cameraFrame(const OrbitCamera& camera) {
  const Basis basis = basisOf(camera.up);
  const float azimuth = glm::radians(camera.azimuthDegrees);
  const float elevation = glm::radians(std::clamp(camera.elevationDegrees, -90.0f, 90.0f));
  const glm::vec3 across = std::cos(azimuth) * basis.first + std::sin(azimuth) * basis.second;
  const glm::vec3 towardsEye = std::cos(elevation) * across + std::sin(elevation) * basis.up;
  CameraFrame frame;
  frame.eye = camera.target + camera.distance * towardsEye;
  frame.forward = -towardsEye;
  // forward x up, normalised, at every elevation below 90 degrees; also defined at 90.
  frame.right = -std::sin(azimuth) * basis.first + std::cos(azimuth) * basis.second;
  frame.up = glm::cross(frame.right, frame.forward);
  return frame;
}

float halfHeightAtUnitDistance(const OrbitCamera& camera) {
  return std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
}

std::optional<NamedView> namedView(std::string_view name, Axis up) {
  if (name == "iso") return NamedView{45.0f, glm::degrees(std::atan(1.0f / std::sqrt(2.0f)))};
  const std::optional<Axis> from = parseAxis(name);
  if (!from || name.size() != 2) return std::nullopt;
  // Azimuth -90 turns the first axis after the up axis to the right (cameraFrame's `right`).
  if (from->index == up.index) return NamedView{-90.0f, from->sign == up.sign ? 90.0f : -90.0f};
  const Basis basis = basisOf(up);
  const glm::vec3 v = from->vector();
  return NamedView{glm::degrees(std::atan2(glm::dot(v, basis.second), glm::dot(v, basis.first))),
                   0.0f};
}

std::string namedViewNames() { return "iso, +x, -x, +y, -y, +z, -z"; }

namespace {

// The distance at which every point, grown by `radius`, is in view from camera.target.
float fittingDistance(const OrbitCamera& camera, std::span<const glm::vec3> points, float radius,
                      float aspect) {
  const CameraFrame frame = cameraFrame(camera);
  const float tanHalf = halfHeightAtUnitDistance(camera);
  // For each point, in the camera's frame: across (right), up, and along the view towards the
  // eye, all from the target.
  float distance = 0.0f, halfHeight = 0.0f, nearest = 0.0f;
  for (const glm::vec3& p : points) {
    const glm::vec3 d = p - camera.target;
    const float x = std::abs(glm::dot(d, frame.right)) + radius;
    const float y = std::abs(glm::dot(d, frame.up)) + radius;
    const float towards = radius - glm::dot(d, frame.forward);
    const float needed = std::max(y, x / aspect);  // half-height that holds this point
    halfHeight = std::max(halfHeight, needed);
    nearest = std::max(nearest, towards);
    // Perspective: the point is inside when its depth (distance - towards) times tanHalf
    // covers `needed`.
    distance = std::max(distance, towards + kMargin * needed / tanHalf);
  }
  if (camera.projection == Projection::Orthographic)
    return kMargin * halfHeight / tanHalf;  // the view's height; the eye is placed apart
  return std::max(distance, nearest + 1e-3f);
}

// Moves the target across the view so that the points' image is centred (their extents on
// either side of the image's centre balance), keeping the distance.
void centreImage(OrbitCamera& camera, std::span<const glm::vec3> points, float radius) {
  const CameraFrame frame = cameraFrame(camera);
  const bool perspective = camera.projection == Projection::Perspective;
  glm::vec2 lowest(INFINITY), highest(-INFINITY);  // in the plane across the view at the target
  for (const glm::vec3& p : points) {
    const glm::vec3 d = p - frame.eye;
    const float depth = perspective ? glm::dot(d, frame.forward) : camera.distance;
    const glm::vec2 across(glm::dot(d, frame.right), glm::dot(d, frame.up));
    const glm::vec2 at = across / std::max(depth, 1e-6f) * camera.distance;
    lowest = glm::min(lowest, at - radius), highest = glm::max(highest, at + radius);
  }
  const glm::vec2 middle = 0.5f * (lowest + highest);
  camera.target += middle.x * frame.right + middle.y * frame.up;
}

}  // namespace

OrbitCamera framePoints(OrbitCamera camera, std::span<const glm::vec3> points, float radius,
                        float aspect, float zoomFactor, std::optional<glm::vec3> target) {
  glm::vec3 lower(INFINITY), upper(-INFINITY);
  for (const glm::vec3& p : points) lower = glm::min(lower, p), upper = glm::max(upper, p);
  if (points.empty()) lower = upper = glm::vec3(0.0f);
  camera.target = target.value_or(0.5f * (lower + upper));
  camera.distance = fittingDistance(camera, points, radius, aspect);
  if (!target && !points.empty()) {
    // Twice: in perspective, moving the target changes how far the points reach.
    for (int pass = 0; pass < 2; ++pass) {
      centreImage(camera, points, radius);
      camera.distance = fittingDistance(camera, points, radius, aspect);
    }
  }
  camera.distance /= std::max(zoomFactor, 1e-3f);
  if (!(camera.distance > 0.0f) || !std::isfinite(camera.distance)) camera.distance = 1.0f;
  return camera;
}

OrbitCamera frameBox(OrbitCamera camera, glm::vec3 lower, glm::vec3 upper, float aspect,
                     float zoomFactor, std::optional<glm::vec3> target) {
  std::array<glm::vec3, 8> corners;
  for (int corner = 0; corner < 8; ++corner)
    corners[corner] = {(corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                       (corner & 4) ? upper.z : lower.z};
  return framePoints(camera, corners, 0.0f, aspect, zoomFactor,
                     target.value_or(0.5f * (lower + upper)));
}

std::optional<glm::vec2> projectToImage(const OrbitCamera& camera, float width, float height,
                                        glm::vec3 point) {
  const CameraFrame frame = cameraFrame(camera);
  const float tanHalf = halfHeightAtUnitDistance(camera);
  const float aspect = width / height;
  const glm::vec3 d = point - frame.eye;
  const float x = glm::dot(d, frame.right), y = glm::dot(d, frame.up);
  float scale = camera.distance * tanHalf;  // the view's half-height where the point is
  if (camera.projection == Projection::Perspective) {
    const float depth = glm::dot(d, frame.forward);
    if (!(depth > 0.0f)) return std::nullopt;
    scale = depth * tanHalf;
  }
  const glm::vec2 ndc(x / (scale * aspect), -y / scale);
  return (ndc + 1.0f) * 0.5f * glm::vec2(width, height);
}

void orbit(OrbitCamera& camera, float azimuthDegrees, float elevationDegrees) {
  camera.azimuthDegrees = std::fmod(camera.azimuthDegrees + azimuthDegrees, 360.0f);
  camera.elevationDegrees = std::clamp(camera.elevationDegrees + elevationDegrees, -90.0f, 90.0f);
}

void pan(OrbitCamera& camera, float rightFraction, float upFraction) {
  const CameraFrame frame = cameraFrame(camera);
  const float viewHeight = 2.0f * camera.distance * halfHeightAtUnitDistance(camera);
  camera.target += viewHeight * (rightFraction * frame.right + upFraction * frame.up);
}

void zoom(OrbitCamera& camera, float factor) { camera.distance /= std::max(factor, 1e-3f); }

}  // namespace amrstream::render
