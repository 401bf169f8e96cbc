#pragma once
// The orientation triad for figures: in the bottom-left corner, lines from one origin along the
// screen directions of +x, +y and +z in red, green and blue, each as long as the axis looks (one
// pointing at the viewer is short), named at its tip.

#include <array>
#include <cstdint>
#include <glm/vec2.hpp>

#include "render/camera.hpp"
#include "render/image/image.hpp"
#include "render/image/placed_text.hpp"

namespace amrstream::render {

struct TriadArm {
  int axis = 0;  // 0, 1, 2: x, y, z
  // origin + armLength * (dot(axis, right), -dot(axis, up)), with right and up of cameraFrame.
  glm::vec2 tip{0.0f};
  float towardsViewer = 0.0f;  // -dot(axis, forward)
  Rgba8 colour;
  // "x", "y" or "z" beyond the tip; for an arm shorter than a third of armLength, beside the
  // origin away from the other two arms.
  PlacedText label;
};

struct TriadLayout {
  int labelPixelSize = 11;
  float lineWidth = 1.5f;
  float armLength = 0.0f;        // the length of an arm parallel to the image
  glm::vec2 origin{0.0f};        // the centre of `area`
  PixelRect area;                // triadArea: every arm and label lies inside it
  std::array<TriadArm, 3> arms;  // x, y, z
};

// The square in the bottom-left corner that the triad takes, as far from the image's edges as
// the colour bar is from them. The scale bar goes above it.
PixelRect triadArea(std::uint32_t height, int labelPixelSize);

// labelPixelSize: overlayLabelPixelSize suits.
TriadLayout layoutTriad(const OrbitCamera& camera, std::uint32_t width, std::uint32_t height,
                        int labelPixelSize);

// Each arm and its label in its colour, the arms pointing at the viewer over the others.
void drawTriad(Image& image, const TriadLayout& layout);

}  // namespace amrstream::render
