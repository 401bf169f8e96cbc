#pragma once
// The tracing backends (docs/backends.md) and how `auto` chooses among them.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "vk/capability.hpp"
#include "vk/device_report.hpp"

namespace amrstream::gpu {

enum class Backend { RayQuery, Pipeline, Compute, Cpu };

std::string_view backendName(Backend backend);  // "rayquery", "pipeline", "compute", "cpu"
std::optional<Backend> parseBackend(std::string_view name);

// What a GPU backend needs of the device; empty for Cpu.
vk::CapabilitySet requiredCapabilities(Backend backend);

// The `auto` choice on one device: rayquery, then pipeline, then compute, else cpu; `why` says
// what was chosen and what was missing for the better ones.
Backend chooseBackend(const vk::DeviceReport* device, std::string& why);

}  // namespace amrstream::gpu
