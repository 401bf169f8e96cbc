#include "render/image/colour_map.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include "render/image/colour_map_controls.hpp"

namespace amrstream::render {
namespace {

struct NamedMap {
  ColourMap map;
  std::string_view name;
};

constexpr std::array kNamedMaps = {
    NamedMap{ColourMap::Viridis, "viridis"}, NamedMap{ColourMap::Magma, "magma"},
    NamedMap{ColourMap::Inferno, "inferno"}, NamedMap{ColourMap::Plasma, "plasma"},
    NamedMap{ColourMap::Cividis, "cividis"}, NamedMap{ColourMap::CoolWarm, "coolwarm"},
    NamedMap{ColourMap::RdBu, "rdbu"},       NamedMap{ColourMap::Twilight, "twilight"},
};

bool equalIgnoringCase(std::string_view a, std::string_view b) {
  return std::ranges::equal(a, b, [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) ==
           std::tolower(static_cast<unsigned char>(y));
  });
}

glm::vec3 colourOf(const detail::ColourControl& control) {
  return {control.r, control.g, control.b};
}

}  // namespace

std::optional<ColourMap> parseColourMap(std::string_view name) {
  for (const NamedMap& named : kNamedMaps) {
    if (equalIgnoringCase(name, named.name)) return named.map;
  }
  return std::nullopt;
}

std::string_view colourMapName(ColourMap map) {
  for (const NamedMap& named : kNamedMaps) {
    if (named.map == map) return named.name;
  }
  return "unknown";
}

std::string colourMapNames() {
  std::string names;
  for (const NamedMap& named : kNamedMaps) {
    if (!names.empty()) names += ", ";
    names += named.name;
  }
  return names;
}

glm::vec3 sampleColourMap(ColourMap map, float t) {
  t = std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, 1.0f);
  const std::span<const detail::ColourControl> controls = detail::colourControls(map);
  // The first control at or after t; the controls start at exactly 0 and end at exactly 1.
  const auto upper = std::ranges::lower_bound(controls, t, {}, &detail::ColourControl::t);
  if (upper->t == t) return colourOf(*upper);  // the published value itself, unrounded
  const detail::ColourControl& high = *upper;
  const detail::ColourControl& low = *(upper - 1);
  const float f = (t - low.t) / (high.t - low.t);
  return colourOf(low) + f * (colourOf(high) - colourOf(low));
}

std::vector<glm::vec3> colourMapTable(ColourMap map, std::size_t entries) {
  std::vector<glm::vec3> table(entries);
  for (std::size_t i = 0; i < entries; ++i) {
    const double t = entries == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(entries - 1);
    table[i] = sampleColourMap(map, static_cast<float>(t));
  }
  return table;
}

}  // namespace amrstream::render
