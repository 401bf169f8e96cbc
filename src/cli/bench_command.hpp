#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "amrstream/mpi_world.hpp"

namespace amrstream::cli {

// `amrstream bench INPUT`: the paper's performance experiment on every backend. `commandLine` is
// recorded in the JSON output. Under mpirun, over the ranks of `world` (which must outlive the
// parse): each row's particles shared out among them.
void addBenchCommand(CLI::App& app, const std::string& commandLine, const MpiWorld& world);

}  // namespace amrstream::cli
