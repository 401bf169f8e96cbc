#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream render INPUT [trace options] [render options] --out image.png`
void addRenderCommand(CLI::App& app);

}  // namespace amrstream::cli
