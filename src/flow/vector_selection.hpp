#pragma once
// Chooses the three channels that form the traced vector.

#include <array>
#include <string>
#include <vector>

#include "bricks/amr_field.hpp"

namespace amrstream::flow {

struct VectorChannels {
  std::array<std::string, 3> channels;
  std::string name;  // the name of the vector in outputs, e.g. "vel" for velx,vely,velz
};

// A dataset's channel names, known before its values are read (formats::readExaCells).
struct ChannelCatalog {
  std::string source;  // prefixes every error
  std::vector<std::string> names;

  bool has(const std::string& name) const;
  // Throws InputError naming the source and listing the channels when `name` is absent, as
  // AmrField::channel does.
  void require(const std::string& name) const;
  std::string list() const;  // "a, b, c", or "none"
};
ChannelCatalog catalogOf(const bricks::AmrField& field);

// `request` is "a,b,c" or empty. Empty picks the first known velocity triplet, then the first
// known magnetic-field triplet. Throws InputError naming the source, the missing channel or the
// available channels.
VectorChannels chooseVectorChannels(const ChannelCatalog& channels, const std::string& request);
VectorChannels chooseVectorChannels(const bricks::AmrField& field, const std::string& request);

}  // namespace amrstream::flow
