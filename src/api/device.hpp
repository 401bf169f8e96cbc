#pragma once
// The backend a request resolves to and the Vulkan context made for it.

#include <string>

#include "amrstream/backend.hpp"
#include "amrstream/log.hpp"
#include "gpu/backend.hpp"
#include "vk/context.hpp"

namespace amrstream {

struct BackendChoice {
  gpu::Backend backend;
  std::string deviceFilter;  // empty: the default device
};

// What the backend is for: tracing alone may fall back to the CPU reference, rendering needs a
// Vulkan device; a slice's LIC falls back as tracing does and otherwise takes `compute`.
enum class BackendUse { Trace, Render, Slice };

// Resolves `auto` (saying what was chosen and why) or parses the named backend (InputError for
// an unknown name). For tracing, `auto` picks the fastest: a GPU backend on a GPU, the CPU
// reference when the only Vulkan device is a software one (lavapipe), which traces several times
// slower than the CPU path. For a slice's LIC, `compute` on a GPU: its one dispatch per plane
// runs as fast there as the others' and its device setup is the shortest (0.28 s against the
// pipeline's 0.44 s on an H100).
BackendChoice chooseBackend(const BackendRequest& request, BackendUse use = BackendUse::Render,
                            const Log& log = {});

// A context for the choice's backend and device, plus `extra` capabilities. Throws
// vk::ContextError naming what is missing.
vk::Context createContext(const BackendRequest& request, const BackendChoice& choice,
                          vk::CapabilitySet extra = {});

// Throws when the context's validation layer reported errors.
void checkValidation(const vk::Context& ctx);

}  // namespace amrstream
