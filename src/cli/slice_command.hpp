#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream slice INPUT --normal z --lic --out slice.png`: a plane through the data with a
// channel on it, the in-plane field lines and a LIC texture, as a figure.
void addSliceCommand(CLI::App& app);

}  // namespace amrstream::cli
