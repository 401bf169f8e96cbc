#pragma once
// The colour maps for scalar colouring: sRGB colours, piecewise linear between published control
// points (colour_map_controls.hpp says which).

#include <cstddef>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace amrstream::render {

enum class ColourMap {
  Viridis,   // matplotlib's perceptually uniform sequential map
  Magma,     // matplotlib's dark-to-light sequential map
  Inferno,   // matplotlib's black-red-yellow sequential map
  Plasma,    // matplotlib's blue-red-yellow sequential map
  Cividis,   // matplotlib's blue-yellow sequential map, for colour-vision deficiency
  CoolWarm,  // Moreland's diverging blue-grey-red map
  RdBu,      // ColorBrewer's diverging map, blue at low values and red at high ones
  Twilight,  // matplotlib's cyclic map: its two ends are the same colour
};

// A name of colourMapNames(), in any case; nullopt for anything else.
std::optional<ColourMap> parseColourMap(std::string_view name);
std::string_view colourMapName(ColourMap map);
// "viridis, magma, inferno, plasma, cividis, coolwarm, rdbu, twilight", for error messages.
std::string colourMapNames();

// The colour at t, sRGB in [0,1]; t is clamped to [0,1] and NaN reads as 0.
glm::vec3 sampleColourMap(ColourMap map, float t);
// `entries` uniform samples: entry i at t = i / (entries - 1), so the first is at 0, the last at 1.
std::vector<glm::vec3> colourMapTable(ColourMap map, std::size_t entries = 256);

}  // namespace amrstream::render
