#include "render/annotations/triad.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "render/annotations/line_drawing.hpp"
#include "render/annotations/overlay_text.hpp"
#include "render/image/font.hpp"

namespace amrstream::render {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};
constexpr Rgba8 kAxisColours[] = {{230, 60, 50, 255}, {70, 180, 70, 255}, {60, 120, 240, 255}};
// Arms shorter than this fraction of armLength are named beside the origin.
constexpr float kShortArm = 1.0f / 3.0f;

float armLengthFor(int labelPixelSize) { return 3.0f * labelPixelSize; }
float labelGapFor(int labelPixelSize) { return std::max(2.0f, 0.25f * labelPixelSize); }

// Where a short arm is named: away from the other two arms, or down and left when they cancel.
glm::vec2 awayFrom(glm::vec2 first, glm::vec2 second) {
  const glm::vec2 away = -(first + second);
  const float length = glm::length(away);
  return length > 1e-3f ? away / length : glm::normalize(glm::vec2(-1.0f, 1.0f));
}

}  // namespace

PixelRect triadArea(std::uint32_t height, int labelPixelSize) {
  const Font& font = defaultFont();
  int widestName = 0;
  for (const char* name : kAxisNames)
    widestName = std::max(widestName, font.textWidth(name, labelPixelSize));
  // An arm, the gap to its label and the label, whichever way the label is pushed out.
  const float reach = armLengthFor(labelPixelSize) + labelGapFor(labelPixelSize) + widestName +
                      font.lineMetrics(labelPixelSize).height() + 1.0f;
  const int side = 2 * static_cast<int>(std::ceil(reach));
  const int margin = std::max(4, labelPixelSize / 2);
  return {margin, static_cast<int>(height) - margin - side, side, side};
}

// The triad's place does not depend on the image's width.
TriadLayout layoutTriad(const OrbitCamera& camera, std::uint32_t /*width*/, std::uint32_t height,
                        int labelPixelSize) {
  const CameraFrame frame = cameraFrame(camera);
  TriadLayout layout;
  layout.labelPixelSize = labelPixelSize;
  layout.lineWidth = std::max(1.5f, labelPixelSize / 8.0f);
  layout.armLength = armLengthFor(labelPixelSize);
  layout.area = triadArea(height, labelPixelSize);
  layout.origin = glm::vec2(layout.area.x, layout.area.y) + 0.5f * glm::vec2(layout.area.width);

  std::array<glm::vec2, 3> screen;  // each axis's direction on screen, as long as it looks
  for (int axis = 0; axis < 3; ++axis) {
    glm::vec3 direction(0.0f);
    direction[axis] = 1.0f;
    screen[axis] = {glm::dot(direction, frame.right), -glm::dot(direction, frame.up)};
    TriadArm& arm = layout.arms[axis];
    arm.axis = axis;
    arm.tip = layout.origin + layout.armLength * screen[axis];
    arm.towardsViewer = -glm::dot(direction, frame.forward);
    arm.colour = kAxisColours[axis];
  }
  const float gap = labelGapFor(labelPixelSize);
  for (int axis = 0; axis < 3; ++axis) {
    TriadArm& arm = layout.arms[axis];
    const float length = glm::length(screen[axis]);
    const glm::vec2 outwards = length >= kShortArm
                                   ? screen[axis] / length
                                   : awayFrom(screen[(axis + 1) % 3], screen[(axis + 2) % 3]);
    arm.label =
        placeTextBeyond(kAxisNames[axis], arm.tip + gap * outwards, outwards, labelPixelSize);
  }
  return layout;
}

void drawTriad(Image& image, const TriadLayout& layout) {
  std::array<const TriadArm*, 3> backToFront{&layout.arms[0], &layout.arms[1], &layout.arms[2]};
  std::sort(backToFront.begin(), backToFront.end(), [](const TriadArm* a, const TriadArm* b) {
    return a->towardsViewer < b->towardsViewer;
  });
  for (const TriadArm* arm : backToFront) {
    drawLine(image, layout.origin, arm->tip, layout.lineWidth, arm->colour, LineCap::Round);
    drawPlacedText(image, arm->label, arm->colour, layout.labelPixelSize);
  }
}

}  // namespace amrstream::render
