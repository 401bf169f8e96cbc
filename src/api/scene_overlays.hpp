#pragma once
// What a rendered image shows besides the tubes: the colour bars, the axes, the orientation triad
// and the scale bar, and the colours of the background and outline they are drawn against.

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "amrstream/dataset_info.hpp"
#include "api/render_scene.hpp"
#include "render/image/colour_bar.hpp"

namespace amrstream {

// A colour as --background takes it: white, black, #rrggbb or R,G,B in [0, 1]. Throws
// InputError naming `option` for anything else.
glm::vec3 parseColour(const std::string& text, const char* option);

// Outlines (and overlay lines) stand out from the background: dark on light, light on dark.
glm::vec3 outlineColourOn(glm::vec3 background);

// The colour bars drawOverlays draws: the tubes', then the context volume's above it.
std::vector<render::ColourBar> colourBarsOf(const RenderOptions& o, const RenderScene& scene);

// The height in pixels of the band at the bottom of a width x height image that the colour bars
// `o` asks for cover (0 without them): the camera frames the scene above it.
int colourBarsHeight(const RenderOptions& o, const RenderScene& scene, std::uint32_t width,
                     std::uint32_t height);

// Draws the axes, triad and scale bar `o` asks for and, with `colourBars`, the tubes' colour bar
// and the context volume's above it; light bars on a light background.
void drawOverlays(render::Image& image, const RenderOptions& o, const RenderScene& scene,
                  const flow::VectorVolume& volume, const DatasetInfo& info, bool colourBars);

}  // namespace amrstream
