#include "viewer/view_overlays.hpp"

#include <imgui.h>

#include "render/annotations/axes.hpp"
#include "render/annotations/scale_bar.hpp"
#include "render/annotations/triad.hpp"
#include "render/image/font.hpp"
#include "render/scene_space.hpp"

namespace amrstream::viewer {
namespace {

// Layouts are in framebuffer pixels; ImGui draws in window coordinates.
struct Canvas {
  ImDrawList* draw;
  glm::vec2 scale;  // framebuffer pixels per window unit

  ImVec2 at(glm::vec2 pixel) const { return ImVec2(pixel.x / scale.x, pixel.y / scale.y); }
  void line(glm::vec2 from, glm::vec2 to, ImU32 colour, float width) const {
    draw->AddLine(at(from), at(to), colour, width / scale.x);
  }
  void text(const render::PlacedText& placed, ImU32 colour) const {
    if (placed.text.empty()) return;
    draw->AddText(at({placed.box.x, placed.box.y}), colour, placed.text.c_str());
  }
};

ImU32 imguiColour(glm::vec3 c) { return ImGui::GetColorU32(ImVec4(c.r, c.g, c.b, 1.0f)); }

}  // namespace

void drawSceneOverlays(const RenderScene& scene, const RenderOptions& look,
                       const flow::VectorVolume& volume, const DatasetInfo& info) {
  const ImGuiIO& io = ImGui::GetIO();
  const glm::vec2 scale(io.DisplayFramebufferScale.x, io.DisplayFramebufferScale.y);
  const auto w = static_cast<std::uint32_t>(io.DisplaySize.x * scale.x);
  const auto h = static_cast<std::uint32_t>(io.DisplaySize.y * scale.y);
  if (w < kMinImageSide || h < kMinImageSide || !(scale.x > 0.0f)) return;
  const Canvas canvas{ImGui::GetBackgroundDrawList(), scale};
  const int size = render::overlayLabelPixelSize(w, h);
  const ImU32 ink = imguiColour(glm::min(scene.settings.outlineColour * 1.15f, glm::vec3(1.0f)));
  if (look.axes) {
    const auto [lower, upper] = axesBounds(look, scene, volume);
    const render::AxesLayout axes =
        render::layoutAxes(scene.camera, w, h, lower, upper,
                           render::sceneTransformOf(volume.transform), size, shortLengthUnit(info));
    for (const render::AxisLayout& axis : axes.axes) {
      if (!axis.shown) continue;
      canvas.line(axis.pixelStart, axis.pixelEnd, ink, axes.lineWidth);
      for (const render::AxisTick& tick : axis.ticks) {
        canvas.line(tick.pixel, tick.markEnd, ink, axes.lineWidth);
        canvas.text(tick.label, ink);
      }
      canvas.text(axis.name, ink);
    }
  }
  if (look.triad) {
    const render::TriadLayout triad = render::layoutTriad(scene.camera, w, h, size);
    for (const render::TriadArm& arm : triad.arms) {
      const ImU32 colour = IM_COL32(arm.colour.r, arm.colour.g, arm.colour.b, 255);
      canvas.line(triad.origin, arm.tip, colour, triad.lineWidth);
      canvas.text(arm.label, colour);
    }
  }
  if (look.scaleBar) {
    const render::ScaleBarLayout bar = render::layoutScaleBar(
        scene.camera, w, h, render::sceneUnitLength(volume.transform), shortLengthUnit(info), size);
    if (bar.length > 0.0) {
      canvas.line(bar.start, bar.end, ink, bar.thickness);
      for (const glm::vec2 end : {bar.start, bar.end})
        canvas.line(end - glm::vec2(0.0f, bar.endHeight / 2),
                    end + glm::vec2(0.0f, bar.endHeight / 2), ink, bar.thickness);
      canvas.text(bar.label, ink);
    }
  }
}

}  // namespace amrstream::viewer
