#include "vector_selection.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <vector>

#include "amrstream/closest_name.hpp"
#include "amrstream/error.hpp"
#include "gradient_request.hpp"

namespace amrstream::flow {

namespace {

// Velocity first, then magnetic field; names as the simulation codes write them.
const std::array<std::array<const char*, 3>, 12> kKnownTriplets{{
    {"velx", "vely", "velz"},
    {"velocity_x", "velocity_y", "velocity_z"},  // yt's names
    {"x-velocity", "y-velocity", "z-velocity"},
    {"x_velocity", "y_velocity", "z_velocity"},
    {"vx", "vy", "vz"},
    {"U", "V", "W"},
    {"u", "v", "w"},
    {"magx", "magy", "magz"},
    {"Bx", "By", "Bz"},
    {"bx", "by", "bz"},
    {"x-magnetic", "y-magnetic", "z-magnetic"},
    {"magnetic_field_x", "magnetic_field_y", "magnetic_field_z"},
}};

std::string trimSeparators(std::string s) {
  while (!s.empty() && (s.front() == '_' || s.front() == '-')) s.erase(s.begin());
  while (!s.empty() && (s.back() == '_' || s.back() == '-')) s.pop_back();
  return s;
}

// "velx,vely,velz" -> "vel"; "x-velocity,y-velocity,z-velocity" -> "velocity"; Gerris' "U,V,W"
// (and "u,v,w") -> "velocity"; otherwise the names joined with '_'.
std::string vectorName(const std::array<std::string, 3>& given) {
  // A 2D vector's name comes from its two channels.
  const std::array<std::string, 3> c{given[0], given[1], given[2].empty() ? given[1] : given[2]};
  if ((c[0] == "U" && c[1] == "V" && c[2] == "W") || (c[0] == "u" && c[1] == "v" && c[2] == "w"))
    return "velocity";
  const std::size_t shortest = std::min({c[0].size(), c[1].size(), c[2].size()});
  std::size_t prefix = 0, suffix = 0;
  while (prefix < shortest && c[0][prefix] == c[1][prefix] && c[0][prefix] == c[2][prefix])
    ++prefix;
  const auto back = [&](int i, std::size_t k) { return c[i][c[i].size() - 1 - k]; };
  while (suffix < shortest && back(0, suffix) == back(1, suffix) &&
         back(0, suffix) == back(2, suffix))
    ++suffix;
  if (std::string name = trimSeparators(c[0].substr(0, prefix)); !name.empty()) return name;
  if (std::string name = trimSeparators(c[0].substr(c[0].size() - suffix)); !name.empty())
    return name;
  return c[0] + "_" + c[1] + "_" + c[2];
}

// The gradient of a scalar channel the catalog must have.
VectorChannels chosenGradient(const ChannelCatalog& field, const GradientRequest& gradient) {
  const std::string& name = gradient.scalar;
  if (!field.has(name))
    throw settingError(
        "vector", fmt::format("no channel '{}' in {} to take the gradient of{}; "
                              "the channels are: {}",
                              name, field.source, didYouMean(name, field.names), field.list()));
  return gradientVector(gradient);
}

}  // namespace

std::vector<std::string> VectorChannels::sourceChannels() const {
  if (isGradient()) return {gradientOf};
  std::vector<std::string> names;
  for (const std::string& name : channels)
    if (!name.empty()) names.push_back(name);
  return names;
}

bool ChannelCatalog::has(const std::string& name) const {
  return std::find(names.begin(), names.end(), name) != names.end();
}

void ChannelCatalog::require(const std::string& name) const {
  if (!has(name))
    throw InputError(source, fmt::format("no channel named '{}'{}; the channels are: {}", name,
                                         didYouMean(name, names), list()));
}

std::string ChannelCatalog::list() const {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "none" : text;
}

ChannelCatalog catalogOf(const bricks::AmrField& field) {
  ChannelCatalog catalog{field.source(), {}, field.info().dimensions};
  for (const Channel& c : field.channels()) catalog.names.push_back(c.name);
  return catalog;
}

VectorChannels chooseVectorChannels(const bricks::AmrField& field, const std::string& request) {
  return chooseVectorChannels(catalogOf(field), request);
}

VectorChannels chooseVectorChannels(const ChannelCatalog& field, const std::string& request) {
  VectorChannels result;
  const bool planar = field.dimensions == 2;
  if (request.empty()) {
    for (const auto& triplet : kKnownTriplets) {
      if (field.has(triplet[0]) && field.has(triplet[1]) && (planar || field.has(triplet[2]))) {
        result.channels = {triplet[0], triplet[1], planar ? "" : triplet[2]};
        result.name = vectorName(result.channels);
        return result;
      }
    }
    throw InputError(field.source,
                     fmt::format("no velocity or magnetic field channels found; choose {} with "
                                 "{{vector}} {} (channels: {})",
                                 planar ? "two" : "three", planar ? "a,b" : "a,b,c", field.list()));
  }

  if (request == kNoVector) {
    result.name = kNoVector;
    return result;
  }
  if (const std::optional<GradientRequest> gradient = parseGradientRequest(request))
    return chosenGradient(field, *gradient);
  std::vector<std::string> names;
  std::istringstream parts(request);
  for (std::string part; std::getline(parts, part, ',');) names.push_back(part);
  const bool counted = planar ? names.size() == 2 || names.size() == 3 : names.size() == 3;
  if (!counted || request.back() == ',')
    throw InputError(field.source,
                     fmt::format("{{vector}} '{}' must name exactly {} separated by commas, or be "
                                 "grad(NAME) or -grad(NAME)",
                                 request,
                                 planar ? "two channels (the data are 2D; a third is left out)"
                                        : "three channels"));
  std::copy(names.begin(), names.begin() + 2, result.channels.begin());
  if (!planar) result.channels[2] = names[2];
  for (const std::string& name : result.sourceChannels()) field.require(name);
  result.name = vectorName(result.channels);
  return result;
}

}  // namespace amrstream::flow
