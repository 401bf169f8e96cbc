#pragma once
// The overlays of `render` (axes, orientation triad, scale bar) in the viewer's window: the same
// layouts (src/render/annotations), drawn with Dear ImGui's lines and text over the scene.

#include "amrstream/rendering.hpp"
#include "bricks/dataset_info.hpp"

namespace amrstream::cli {

// Draws what `look` asks for (axes, triad, scaleBar) for the scene's camera, behind the controls.
void drawSceneOverlays(const RenderScene& scene, const RenderOptions& look,
                       const flow::VectorVolume& volume, const bricks::DatasetInfo& info);

}  // namespace amrstream::cli
