#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace amrstream::cli {

// `amrstream bench INPUT`: the paper's performance experiment on every backend. `commandLine` is
// recorded in the JSON output.
void addBenchCommand(CLI::App& app, const std::string& commandLine);

}  // namespace amrstream::cli
