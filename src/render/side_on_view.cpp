#include "side_on_view.hpp"

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace amrstream::render {
namespace {

// The view from above wins where at most this share of the lines' length runs along the up axis:
// lines (nearly) across it.
constexpr float kFlatTolerance = 1e-3f;

glm::dmat3 orientationTensor(std::span<const shared::TubeSegment> segments) {
  glm::dmat3 tensor(0.0);
  for (const shared::TubeSegment& s : segments) {
    const glm::dvec3 along = glm::dvec3(s.b) - glm::dvec3(s.a);
    const double length = glm::length(along);
    if (length > 0.0) tensor += glm::outerProduct(along, along) / length;
  }
  return tensor;
}

float fractionAlong(const glm::dmat3& tensor, glm::vec3 direction) {
  const double trace = tensor[0][0] + tensor[1][1] + tensor[2][2];
  if (!(trace > 0.0)) return 0.0f;
  const glm::dvec3 d = glm::normalize(glm::dvec3(direction));
  return static_cast<float>(glm::dot(d, tensor * d) / trace);
}

}  // namespace

float lengthAlong(std::span<const shared::TubeSegment> segments, glm::vec3 direction) {
  return fractionAlong(orientationTensor(segments), direction);
}

OrbitCamera sideOn(OrbitCamera camera, std::span<const shared::TubeSegment> segments) {
  const glm::dmat3 tensor = orientationTensor(segments);
  const auto along = [&](const OrbitCamera& view) {
    return fractionAlong(tensor, cameraFrame(view).forward);
  };
  const auto turned = [&](float azimuth, float elevation) {
    OrbitCamera view = camera;
    view.azimuthDegrees = azimuth, view.elevationDegrees = elevation;
    return view;
  };
  // Lines that lie across the up axis (2D data) are seen from above, without foreshortening.
  const std::string upName{camera.up.sign > 0.0f ? '+' : '-', "xyz"[camera.up.index]};
  if (const std::optional<NamedView> above = namedView(upName, camera.up)) {
    const OrbitCamera view = turned(above->azimuthDegrees, above->elevationDegrees);
    if (along(view) <= kFlatTolerance && !segments.empty()) return view;
  }
  const float kept = along(camera);
  std::vector<std::pair<float, float>> sides;  // azimuth, fraction along
  float least = kept;
  for (int azimuth = -180; azimuth < 180; azimuth += 5) {
    const float a = along(turned(float(azimuth), camera.elevationDegrees));
    sides.emplace_back(float(azimuth), a);
    least = std::min(least, a);
  }
  if (!(least + kSideOnGain <= kept)) return camera;
  // Of the side views nearly as good as the best, the one nearest the camera's azimuth.
  const auto turn = [&](float azimuth) {
    const float d = std::fmod(std::abs(azimuth - camera.azimuthDegrees), 360.0f);
    return std::min(d, 360.0f - d);
  };
  float chosen = camera.azimuthDegrees;
  for (const auto& [azimuth, a] : sides)
    if (a <= least + kSideOnSlack &&
        (chosen == camera.azimuthDegrees || turn(azimuth) < turn(chosen)))
      chosen = azimuth;
  return turned(chosen, camera.elevationDegrees);
}

}  // namespace amrstream::render
