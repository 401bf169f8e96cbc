#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream convert INPUT OUT.exa`: writes any input as ExaBricks files.
void addConvertCommand(CLI::App& app);

}  // namespace amrstream::cli
