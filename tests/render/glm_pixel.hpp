#pragma once
// Where glm's own view and projection matrices put a point, in pixels from the top-left corner:
// an oracle for the camera's frame, framing and projectToImage (and what is placed with them)
// that shares none of their code.

#include <glm/gtc/matrix_transform.hpp>

#include "render/camera.hpp"

namespace amrstream::render::testing {

inline glm::vec2 glmPixel(const OrbitCamera& camera, float width, float height, glm::vec3 point) {
  const glm::vec3 towardsEye =
      glm::normalize(cameraFrame(camera).eye - camera.target) * camera.distance;
  const glm::mat4 view = glm::lookAt(camera.target + towardsEye, camera.target, camera.up.vector());
  const float halfHeight = camera.distance * std::tan(glm::radians(camera.fovYDegrees) / 2.0f);
  const float aspect = width / height;
  const glm::mat4 projection =
      camera.projection == Projection::Perspective
          ? glm::perspective(glm::radians(camera.fovYDegrees), aspect, 1e-3f, 1e6f)
          : glm::ortho(-halfHeight * aspect, halfHeight * aspect, -halfHeight, halfHeight, -1e6f,
                       1e6f);
  const glm::vec4 clip = projection * view * glm::vec4(point, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x + 1.0f) * 0.5f * width, (1.0f - ndc.y) * 0.5f * height};
}

}  // namespace amrstream::render::testing
