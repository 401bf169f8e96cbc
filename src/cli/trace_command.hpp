#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream trace INPUT ... --out traces.vtp`
void addTraceCommand(CLI::App& app);

}  // namespace amrstream::cli
