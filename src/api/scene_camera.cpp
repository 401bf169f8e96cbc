// Where the camera of a rendered scene looks from and what it frames (RenderOptions' camera
// options): rendering.hpp's frameCamera, frameTubes and axesBounds.
#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "amrstream/error.hpp"
#include "api/render_scene.hpp"
#include "api/scene_overlays.hpp"
#include "render/scene_space.hpp"
#include "render/side_on_view.hpp"

namespace amrstream {

namespace {

// What the camera frames, in scene units (render/scene_space.hpp): the corners of --view-box, else
// the tubes' ends (with their radius) or the domain's corners.
struct Framed {
  std::vector<glm::vec3> points;
  float radius = 0.0f;
};

std::vector<glm::vec3> boxCorners(glm::vec3 lower, glm::vec3 upper) {
  std::vector<glm::vec3> corners;
  for (int corner = 0; corner < 8; ++corner)
    corners.push_back({(corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                       (corner & 4) ? upper.z : lower.z});
  return corners;
}

// --view-box in scene units, checked; nullopt without one.
std::optional<std::pair<glm::vec3, glm::vec3>> viewBoxOf(const RenderOptions& o,
                                                         const flow::VectorVolume& volume) {
  if (o.viewBox.empty()) return std::nullopt;
  if (o.viewBox.size() != 6) throw settingError("view_box", "expected 6 numbers x0,y0,z0,x1,y1,z1");
  const glm::dvec3 a(o.viewBox[0], o.viewBox[1], o.viewBox[2]);
  const glm::dvec3 b(o.viewBox[3], o.viewBox[4], o.viewBox[5]);
  if (!glm::all(glm::lessThan(a, b)))
    throw settingError("view_box", "the lower corner must be below the upper one on every axis");
  const WorldTransform scene = render::sceneTransformOf(volume.transform);
  return std::pair{glm::vec3(scene.toCellUnits(a)), glm::vec3(scene.toCellUnits(b))};
}

// The domain's box in scene units.
std::pair<glm::vec3, glm::vec3> domainBox(const flow::VectorVolume& volume) {
  const glm::vec3 scale(render::sceneScaleOf(volume.transform));
  return {glm::vec3(volume.domain.lower) * scale, glm::vec3(volume.domain.upper) * scale};
}

// The box --axes follows, in scene units: --view-box, else what the camera frames (the traces,
// or the domain).
std::pair<glm::vec3, glm::vec3> axesBox(const RenderOptions& o, const RenderScene& scene,
                                        const flow::VectorVolume& volume) {
  if (const auto box = viewBoxOf(o, volume)) return *box;
  if (o.frame == "traces" && scene.tracesBox) return *scene.tracesBox;
  return domainBox(volume);
}

// The traces' tubes: the scene's segments before the outline's.
std::span<const shared::TubeSegment> traceSegments(const RenderScene& scene) {
  return std::span(scene.segments).first(scene.segments.size() - scene.outline.size());
}

Framed framedPoints(const RenderOptions& o, const RenderScene& scene,
                    const flow::VectorVolume& volume, float radius) {
  const std::span<const shared::TubeSegment> segments = traceSegments(scene);
  if (const auto box = viewBoxOf(o, volume)) return {boxCorners(box->first, box->second)};
  if (o.frame != "traces" && o.frame != "domain")
    throw settingError("frame", fmt::format("'{}': choose traces or domain", o.frame));
  if (o.frame == "traces" && !segments.empty()) {
    Framed framed{{}, radius};
    framed.points.reserve(2 * segments.size() + 8);
    for (const shared::TubeSegment& s : segments) {
      framed.points.push_back(s.a);
      framed.points.push_back(s.b);
    }
    if (o.axes) {  // the axes' box stays in view with their labels, flat or not
      const auto [lower, upper] = axesBox(o, scene, volume);
      const std::vector<glm::vec3> corners = boxCorners(lower, upper);
      framed.points.insert(framed.points.end(), corners.begin(), corners.end());
    }
    return framed;
  }
  const auto [lower, upper] = domainBox(volume);
  return {boxCorners(lower, upper)};
}

// The camera the options ask for, before framing.
render::OrbitCamera cameraOf(const RenderOptions& o) {
  render::OrbitCamera camera;
  const std::optional<render::Axis> up = render::parseAxis(o.up);
  if (!up) throw settingError("up", fmt::format("'{}': choose +x, -x, +y, -y, +z or -z", o.up));
  camera.up = *up;
  if (!(o.fovDegrees >= 1.0f && o.fovDegrees <= 150.0f))
    throw settingError("fov", fmt::format("{} degrees is outside 1 to 150", o.fovDegrees));
  camera.fovYDegrees = o.fovDegrees;
  if (o.projection == "orthographic")
    camera.projection = render::Projection::Orthographic;
  else if (o.projection != "perspective")
    throw settingError("projection",
                       fmt::format("'{}': choose perspective or orthographic", o.projection));
  if (!o.view.empty()) {
    if (!o.camera.empty())
      throw settingError("view", "give either {view} or {camera}'s azimuth and elevation");
    const std::optional<render::NamedView> view = render::namedView(o.view, camera.up);
    if (!view)
      throw settingError(
          "view", fmt::format("no view '{}'; choose one of: {}", o.view, render::namedViewNames()));
    camera.azimuthDegrees = view->azimuthDegrees;
    camera.elevationDegrees = view->elevationDegrees;
  } else if (o.camera.size() >= 2) {
    camera.azimuthDegrees = o.camera[0];
    camera.elevationDegrees = std::clamp(o.camera[1], -90.0f, 90.0f);
  }
  return camera;
}

}  // namespace

std::pair<glm::dvec3, glm::dvec3> axesBounds(const RenderOptions& o, const RenderScene& scene,
                                             const flow::VectorVolume& volume) {
  const auto [lower, upper] = axesBox(o, scene, volume);
  const WorldTransform transform = render::sceneTransformOf(volume.transform);
  return {transform.toPhysical(glm::dvec3(lower)), transform.toPhysical(glm::dvec3(upper))};
}

void frameCamera(RenderScene& scene, const RenderOptions& o, const flow::VectorVolume& volume) {
  // Axes need room outside the framed box for their labels.
  const float zoom = o.zoom * (o.camera.size() == 3 ? o.camera[2] : 1.0f) * (o.axes ? 0.8f : 1.0f);
  if (!(zoom > 0.0f) || !std::isfinite(zoom))
    throw settingError(o.camera.size() == 3 ? "camera" : "zoom",
                       "the zoom factor must be positive and finite");
  const Framed framed = framedPoints(o, scene, volume, scene.settings.tubeRadius);
  std::optional<glm::vec3> target;
  if (!o.lookAt.empty()) {
    if (o.lookAt.size() != 3) throw settingError("look_at", "expected 3 numbers x,y,z");
    const WorldTransform scene = render::sceneTransformOf(volume.transform);
    target = glm::vec3(scene.toCellUnits(glm::dvec3(o.lookAt[0], o.lookAt[1], o.lookAt[2])));
  }
  render::OrbitCamera camera = cameraOf(o);
  if (o.view.empty() && o.camera.size() < 2) camera = render::sideOn(camera, traceSegments(scene));
  // Framed above the colour bars' band, so that they cover neither tubes nor labels.
  const float band = float(colourBarsHeight(o, scene, o.width, o.height));
  const float above = float(o.height) - band;
  scene.camera = render::framePoints(camera, framed.points, framed.radius, float(o.width) / above,
                                     zoom, target);
  if (band > 0.0f) {
    render::zoom(scene.camera, above / float(o.height));
    render::pan(scene.camera, 0.0f, -0.5f * band / float(o.height));
  }
}

void frameTubes(RenderScene& scene, const flow::VectorVolume& volume, float aspect) {
  RenderOptions tubes;
  tubes.frame = "traces";
  const Framed framed = framedPoints(tubes, scene, volume, scene.settings.tubeRadius);
  scene.camera = render::framePoints(scene.camera, framed.points, framed.radius, aspect);
}

}  // namespace amrstream
