#pragma once

#include <CLI/CLI.hpp>

#include "amrstream/mpi_world.hpp"

namespace amrstream::cli {

// `amrstream trace INPUT ... --out traces.vtp`; under mpirun, over the ranks of `world`, which
// must outlive the parse.
void addTraceCommand(CLI::App& app, const MpiWorld& world);

}  // namespace amrstream::cli
