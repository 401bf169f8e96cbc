#pragma once
// The viewer's Dear ImGui controls and read-outs, and its mouse camera.

#include <string>

#include "app/input.hpp"
#include "viewer/view_session.hpp"

namespace amrstream::viewer {

struct FrameStats {
  double frameSeconds = 0.0;
  double stepsPerSecond = 0.0;
  std::string device;
};

// What the user asked for through the panel this frame.
struct PanelRequests {
  bool screenshot = false;
  bool exportTraces = false;
  bool frameAll = false;
};

PanelRequests drawViewPanel(ViewSession& session, const FrameStats& stats);

// The colour legend alone in the bottom-right corner, for when the controls are hidden.
void drawLegendOverlay(const RenderScene& scene, const std::optional<render::ValueRange>& middle);

// Left drag orbits, right or middle drag pans, the wheel zooms.
void moveCamera(render::OrbitCamera& camera, const app::InputFrame& input, float viewHeight);

}  // namespace amrstream::viewer
