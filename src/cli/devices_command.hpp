#pragma once

#include <CLI/CLI.hpp>

namespace amrstream::cli {

// `amrstream devices`: the Vulkan devices and the backends each supports.
void addDevicesCommand(CLI::App& app);

}  // namespace amrstream::cli
