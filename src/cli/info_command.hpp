#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream info INPUT`: levels, cells, bounds, channels, bricks and regions.
void addInfoCommand(CLI::App& app);

}  // namespace amrstream::cli
