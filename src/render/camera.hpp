#pragma once
// The orbit camera of the renderer and the viewer: it looks at `target` from `distance` away,
// at an azimuth about +z and an elevation above the xy plane, with +z up on screen. Lengths are
// in finest-cell units, like the tubes.

#include <glm/glm.hpp>
#include <string>

namespace amrstream::render {

struct OrbitCamera {
  glm::vec3 target{0.0f};
  float distance = 1.0f;
  float azimuthDegrees = 35.0f;
  float elevationDegrees = 25.0f;
  float fovYDegrees = 35.0f;

  bool operator==(const OrbitCamera&) const = default;
};

// The eye and its orthonormal frame (forward, right, up).
struct CameraFrame {
  glm::vec3 eye, forward, right, up;
};

CameraFrame cameraFrame(const OrbitCamera& camera);

// Looks at the box's centre from far enough that the whole box is in view at this aspect
// (width / height); `zoom` > 1 moves closer.
OrbitCamera frameBox(glm::vec3 lower, glm::vec3 upper, float aspect, float azimuthDegrees = 35.0f,
                     float elevationDegrees = 25.0f, float zoom = 1.0f);

// Viewer interaction: turn about the target, move the target in the view plane (by fractions of
// the view height), and zoom by a factor (> 1: closer).
void orbit(OrbitCamera& camera, float azimuthDegrees, float elevationDegrees);
void pan(OrbitCamera& camera, float rightFraction, float upFraction);
void zoom(OrbitCamera& camera, float factor);

}  // namespace amrstream::render
