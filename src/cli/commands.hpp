#pragma once
// Every subcommand of `amrstream`, added to the application.

#include <CLI/CLI.hpp>
#include <string>

#include "amrstream/mpi_world.hpp"

namespace amrstream::cli {

// `world` must outlive the parse; `commandLine` is what bench records.
void addCommands(CLI::App& app, const MpiWorld& world, const std::string& commandLine);

}  // namespace amrstream::cli
