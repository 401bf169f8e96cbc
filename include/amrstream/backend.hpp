#pragma once
// Where tracing and rendering run: the backend (`auto`, or a named one) and the Vulkan device,
// and what each device on this machine supports.

#include <string>
#include <vector>

#include "amrstream/settings.hpp"

namespace amrstream {

struct BackendRequest {
  std::string backend{settings::kBackend.shown};  // backend: auto, rayquery, pipeline, compute, cpu
  std::string device{};     // device: a substring of the device name; empty: the default device
  bool validation = false;  // Vulkan validation layers (see validationRequested)
  // Which of the qualifying devices: an MPI rank's local rank, so each takes its host's GPU.
  unsigned deviceSlot = 0;
};

// Validation layers: always in debug builds unless AMRSTREAM_VALIDATION=0, and in release builds
// only with AMRSTREAM_VALIDATION=1.
bool validationRequested();

// A Vulkan device and the backends it runs.
struct DeviceDescription {
  unsigned index = 0;
  std::string name, type, driverName, driverInfo;  // type: "discrete GPU", "CPU", ...
  struct BackendSupport {
    std::string backend;               // rayquery, pipeline, compute
    std::vector<std::string> missing;  // what the device lacks for it; empty: supported
  };
  std::vector<BackendSupport> backends;
  std::string autoRender, autoTrace;  // what `auto` picks on it for each use
  bool software = false;              // a software device (lavapipe): auto traces on the CPU
};

// Every Vulkan device (an empty list: a driver loaded but offers none). Throws when there is no
// Vulkan loader or driver at all.
std::vector<DeviceDescription> describeDevices();

}  // namespace amrstream
