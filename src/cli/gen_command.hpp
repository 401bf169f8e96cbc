#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream gen KIND --out PREFIX`: writes a synthetic dataset as ExaBricks files.
void addGenCommand(CLI::App& app);

}  // namespace amrstream::cli
