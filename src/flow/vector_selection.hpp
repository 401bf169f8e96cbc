#pragma once
// Chooses the traced vector: three channels, or the gradient of a scalar channel (derived from
// the cell values: gradient_vector.hpp), less the velocity of a moving frame.

#include <array>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::flow {

struct VectorChannels {
  // The components' names: the dataset's channels, or a gradient's "d(T)/dx", "d(T)/dy", ...
  // The third is empty for a 2D dataset's vector (ChannelCatalog::dimensions 2): zero.
  std::array<std::string, 3> channels;
  std::string name;  // the name of the vector in outputs, e.g. "vel" for velx,vely,velz
  // Set for grad(NAME) and -grad(NAME): the scalar channel NAME, whose gradient per physical
  // length, times gradientSign, is the vector.
  std::string gradientOf{};
  float gradientSign = 1.0f;
  glm::dvec3 frameVelocity{0.0};  // subtracted from every value: a frame moving at it

  bool isGradient() const { return !gradientOf.empty(); }
  // The dataset's channels the vector is made of: its three (two in 2D), or the gradient's
  // scalar.
  std::vector<std::string> sourceChannels() const;
};

// A dataset's channel names, known before its values are read (formats::readExaCells).
struct ChannelCatalog {
  std::string source;  // prefixes every error
  std::vector<std::string> names;
  int dimensions = 3;  // DatasetInfo::dimensions

  bool has(const std::string& name) const;
  // Throws InputError naming the source and listing the channels when `name` is absent, as
  // AmrField::channel does.
  void require(const std::string& name) const;
  std::string list() const;  // "a, b, c", or "none"
};
ChannelCatalog catalogOf(const bricks::AmrField& field);

// The request for no vector (zeros everywhere): for slices that show a channel alone.
inline constexpr std::string_view kNoVector = "none";

// `request` is "a,b,c", grad(NAME), -grad(NAME), "none" or empty. Empty picks the first known
// velocity triplet, then the first known magnetic-field triplet. For 2D data, whose traces stay in
// their plane, the vector is (a, b, 0): "a,b" or "a,b,c" (c left out), and empty picks the first
// known pair (velx, vely, ...). Throws InputError naming the source, the missing channel or the
// available channels; for a gradient, naming {vector}.
VectorChannels chooseVectorChannels(const ChannelCatalog& channels, const std::string& request);
VectorChannels chooseVectorChannels(const bricks::AmrField& field, const std::string& request);

}  // namespace amrstream::flow
