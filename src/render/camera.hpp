#pragma once
// The orbit camera of the renderer and the viewer: it looks at `target` from `distance` away, at
// an azimuth about the up axis and an elevation above the plane across it, with the up axis up on
// screen. Lengths are in finest-cell units, like the tubes. Perspective or orthographic; an
// orthographic view is as tall as a perspective one at the target (2 distance tan(fovY / 2)), so
// zooming and panning work alike.

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace amrstream::render {

enum class Projection { Perspective, Orthographic };

// An axis of the world: +x, -x, +y, -y, +z or -z.
struct Axis {
  int index = 2;  // 0, 1, 2: x, y, z
  float sign = 1.0f;
  glm::vec3 vector() const;
  bool operator==(const Axis&) const = default;
};
// "+x", "-x", ..., "+z", "-z"; also "x", "y", "z" for the positive ones. nullopt otherwise.
std::optional<Axis> parseAxis(std::string_view name);

struct OrbitCamera {
  glm::vec3 target{0.0f};
  float distance = 1.0f;
  float azimuthDegrees = 35.0f;
  float elevationDegrees = 25.0f;  // -90 to 90
  float fovYDegrees = 35.0f;
  Axis up;
  Projection projection = Projection::Perspective;

  bool operator==(const OrbitCamera&) const = default;
};

// The eye and its orthonormal frame (forward, right, up). Azimuth 0 looks from the first axis
// after `up` in x, y, z order (from +x when z is up, +z when y is up, +y when x is up), and grows
// towards the second.
struct CameraFrame {
  glm::vec3 eye, forward, right, up;
};

CameraFrame cameraFrame(const OrbitCamera& camera);

// tan(fovY / 2): half the view's height at unit distance in front of the eye.
float halfHeightAtUnitDistance(const OrbitCamera& camera);

// A named direction to look from: "iso" (azimuth 45, elevation 35.26: the three axes equally
// foreshortened), or an axis the camera looks from ("+x" looks from +x towards -x). Views along
// the up axis look straight down (or up), with the first axis after it pointing right.
struct NamedView {
  float azimuthDegrees;
  float elevationDegrees;
};
// nullopt for a name that is none of these, or for a view along an axis that is not the up axis
// but parallel to it ("+z" with up "-z" is fine: elevation -90).
std::optional<NamedView> namedView(std::string_view name, Axis up);
// "iso, +x, -x, +y, -y, +z, -z", for messages.
std::string namedViewNames();

// Moves the camera (keeping its direction, field of view and projection) so that it looks at
// `target` (default: the centre of the points' bounding box) from just far enough for every
// point, grown by `radius`, to be in view at this aspect (width / height), with a small margin;
// `zoom` > 1 moves closer. Framing the points rather than their box fits lines that fill a box
// seen along its diagonal.
OrbitCamera framePoints(OrbitCamera camera, std::span<const glm::vec3> points, float radius,
                        float aspect, float zoom = 1.0f,
                        std::optional<glm::vec3> target = std::nullopt);
// The same for the eight corners of a box.
OrbitCamera frameBox(OrbitCamera camera, glm::vec3 lower, glm::vec3 upper, float aspect,
                     float zoom = 1.0f, std::optional<glm::vec3> target = std::nullopt);

// Where a point lands in a width x height image, in pixels from the top-left corner (pixel
// centres at half-integers), as the renderer's rays see it; nullopt behind a perspective eye.
std::optional<glm::vec2> projectToImage(const OrbitCamera& camera, float width, float height,
                                        glm::vec3 point);

// Viewer interaction: turn about the target, move the target in the view plane (by fractions of
// the view height), and zoom by a factor (> 1: closer).
void orbit(OrbitCamera& camera, float azimuthDegrees, float elevationDegrees);
void pan(OrbitCamera& camera, float rightFraction, float upFraction);
void zoom(OrbitCamera& camera, float factor);

}  // namespace amrstream::render
