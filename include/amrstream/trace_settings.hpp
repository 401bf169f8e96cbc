#pragma once
// Settings that `trace` and `bench` read the same way.

#include <optional>
#include <string>

#include "flow/integrator.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream::cli {

// "cell", "time" or "arc" (the CLI checks membership).
flow::StepMode parseStepMode(const std::string& name);

// The step size the user gave, else the default of the mode: 0.25 cell widths, or for `time`
// 1/4 of the finest cell crossed at the volume's maximum speed. Throws InputError unless > 0.
float chooseStepSize(flow::StepMode mode, std::optional<float> requested,
                     const flow::VectorVolume& volume);

// Validation layers: always in debug builds unless AMRSTREAM_VALIDATION=0, and in release builds
// only with AMRSTREAM_VALIDATION=1.
bool validationRequested();

}  // namespace amrstream::cli
