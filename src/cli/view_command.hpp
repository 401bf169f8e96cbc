#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream view INPUT [trace options] [render options]`: the desktop viewer. Without GLFW and
// Dear ImGui at build time the command says so and exits.
void addViewCommand(CLI::App& app);

}  // namespace amrstream::cli
