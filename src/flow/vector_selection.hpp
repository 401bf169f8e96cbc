#pragma once
// Chooses the three channels that form the traced vector.

#include <array>
#include <string>

#include "bricks/amr_field.hpp"

namespace amrstream::flow {

struct VectorChannels {
  std::array<std::string, 3> channels;
  std::string name;  // the name of the vector in outputs, e.g. "vel" for velx,vely,velz
};

// `request` is "a,b,c" or empty. Empty picks the first known velocity triplet, then the first
// known magnetic-field triplet. Throws InputError naming the source, the missing channel or the
// available channels.
VectorChannels chooseVectorChannels(const bricks::AmrField& field, const std::string& request);

}  // namespace amrstream::flow
