#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream resample INPUT --dims N --out FILE.vti`: the reconstructed vector and point data on
// a uniform grid, written as VTK ImageData.
void addResampleCommand(CLI::App& app);

}  // namespace amrstream::cli
