#pragma once
// The overlays of `render` (axes, orientation triad, scale bar) in the viewer's window: the same
// layouts (src/render/annotations), drawn with Dear ImGui's lines and text over the scene.

#include "amrstream/dataset_info.hpp"
#include "api/render_scene.hpp"

namespace amrstream::viewer {

// Draws what `look` asks for (axes, triad, scaleBar) for the scene's camera, behind the controls.
void drawSceneOverlays(const RenderScene& scene, const RenderOptions& look,
                       const flow::VectorVolume& volume, const DatasetInfo& info);

}  // namespace amrstream::viewer
