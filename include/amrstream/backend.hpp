#pragma once
// Picks the tracing backend and device (`auto`, or a named backend and a device name filter) and
// makes a Vulkan context for it.

#include <string>

#include "amrstream/log.hpp"
#include "gpu/backend.hpp"
#include "vk/context.hpp"

namespace amrstream {

struct BackendRequest {
  std::string backend = "auto";  // auto, rayquery, pipeline, compute or cpu
  std::string device;            // a substring of the device name; empty: the default device
  bool validation = false;       // Vulkan validation layers (debug builds, AMRSTREAM_VALIDATION)
  // Which of the qualifying devices (vk::ContextBuilder::deviceSlot): an MPI rank's local rank.
  unsigned deviceSlot = 0;
};

struct BackendChoice {
  gpu::Backend backend;
  std::string deviceFilter;  // empty: the default device
};

// What the backend is for: tracing alone may fall back to the CPU reference, rendering needs a
// Vulkan device.
enum class BackendUse { Trace, Render };

// Resolves `auto` (saying what was chosen and why) or parses the named backend (InputError for
// an unknown name). For tracing, `auto` picks the fastest: a GPU backend on a GPU, the CPU
// reference when the only Vulkan device is a software one (lavapipe), which traces several times
// slower than the CPU path.
BackendChoice chooseBackend(const BackendRequest& request, BackendUse use = BackendUse::Render,
                            const Log& log = {});

// A context for the choice's backend and device, plus `extra` capabilities. Throws
// vk::ContextError naming what is missing.
vk::Context createContext(const BackendRequest& request, const BackendChoice& choice,
                          vk::CapabilitySet extra = {});

// Throws when the context's validation layer reported errors.
void checkValidation(const vk::Context& ctx);

// Validation layers: always in debug builds unless AMRSTREAM_VALIDATION=0, and in release builds
// only with AMRSTREAM_VALIDATION=1.
bool validationRequested();

}  // namespace amrstream
