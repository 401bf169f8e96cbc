#pragma once
// Opens any supported input: `builtin:KIND` (a synthetic dataset) or an ExaBricks `.exa` config.

#include <string>

#include "bricks/amr_field.hpp"
#include "synth/generators.hpp"

namespace amrstream::formats {

// `generatorOptions` sizes builtin datasets. Throws InputError for unknown formats or kinds.
bricks::AmrField loadInput(const std::string& input,
                           const synth::GeneratorOptions& generatorOptions);

}  // namespace amrstream::formats
