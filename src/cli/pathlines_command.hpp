#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream pathlines SNAPSHOT... --out paths.vtp`
void addPathlinesCommand(CLI::App& app);

}  // namespace amrstream::cli
