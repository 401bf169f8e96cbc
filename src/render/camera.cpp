#include "camera.hpp"

#include <algorithm>
#include <cmath>

namespace amrstream::render {

CameraFrame cameraFrame(const OrbitCamera& camera) {
  const float azimuth = glm::radians(camera.azimuthDegrees);
  const float elevation = glm::radians(camera.elevationDegrees);
  const glm::vec3 towardsEye(std::cos(elevation) * std::cos(azimuth),
                             std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  CameraFrame frame;
  frame.eye = camera.target + camera.distance * towardsEye;
  frame.forward = -towardsEye;
  // Elevation stays inside (-90, 90) degrees (orbit() clamps it), so this cross product is safe.
  frame.right = glm::normalize(glm::cross(frame.forward, glm::vec3(0.0f, 0.0f, 1.0f)));
  frame.up = glm::cross(frame.right, frame.forward);
  return frame;
}

OrbitCamera frameBox(glm::vec3 lower, glm::vec3 upper, float aspect, float azimuthDegrees,
                     float elevationDegrees, float zoomFactor) {
  OrbitCamera camera;
  camera.target = 0.5f * (lower + upper);
  camera.azimuthDegrees = azimuthDegrees;
  camera.elevationDegrees = std::clamp(elevationDegrees, -89.0f, 89.0f);
  const float radius = 0.5f * glm::length(upper - lower);
  const float halfFov = glm::radians(camera.fovYDegrees) * 0.5f;
  const float fitHeight = radius / std::sin(halfFov);
  const float fitWidth = radius / std::sin(std::atan(std::tan(halfFov) * std::min(aspect, 1.0f)));
  camera.distance = std::max(fitHeight, fitWidth) / std::max(zoomFactor, 1e-3f);
  return camera;
}

void orbit(OrbitCamera& camera, float azimuthDegrees, float elevationDegrees) {
  camera.azimuthDegrees = std::fmod(camera.azimuthDegrees + azimuthDegrees, 360.0f);
  camera.elevationDegrees = std::clamp(camera.elevationDegrees + elevationDegrees, -89.0f, 89.0f);
}

void pan(OrbitCamera& camera, float rightFraction, float upFraction) {
  const CameraFrame frame = cameraFrame(camera);
  const float viewHeight = 2.0f * camera.distance * std::tan(glm::radians(camera.fovYDegrees) * 0.5f);
  camera.target += viewHeight * (rightFraction * frame.right + upFraction * frame.up);
}

void zoom(OrbitCamera& camera, float factor) {
  camera.distance /= std::max(factor, 1e-3f);
}

}  // namespace amrstream::render
