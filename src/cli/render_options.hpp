#pragma once
// The command-line options of how tubes look, shared by `render` and `view`.

#include <CLI/CLI.hpp>

#include "amrstream/rendering.hpp"

namespace amrstream::cli {

// Adds the options of RenderOptions to `command`.
void addRenderOptions(CLI::App& command, RenderOptions& options);

}  // namespace amrstream::cli
