#pragma once
// Picks the tracing backend and device for `trace --backend B [--device NAME]` and runs the
// trace on it.

#include <functional>
#include <span>
#include <string>

#include "flow/integrator.hpp"
#include "flow/trace_set.hpp"
#include "flow/vector_volume.hpp"
#include "gpu/backend.hpp"
#include "vk/context.hpp"

namespace amrstream::cli {

struct BackendRequest {
  std::string backend = "auto";  // auto, rayquery, pipeline, compute or cpu
  std::string device;            // a substring of the device name; empty: the default device
  bool validation = false;       // Vulkan validation layers (debug builds, AMRSTREAM_VALIDATION)
};

struct BackendChoice {
  gpu::Backend backend;
  std::string deviceFilter;  // empty: the default device
};

// Resolves `auto` (printing what was chosen and why) or parses the named backend.
BackendChoice chooseBackend(const BackendRequest& request);

// A context for the choice's backend and device, plus `extra` capabilities. Throws
// vk::ContextError naming what is missing.
vk::Context createContext(const BackendRequest& request, const BackendChoice& choice,
                          vk::CapabilitySet extra = {});

// Throws when the context's validation layer reported errors.
void checkValidation(const vk::Context& ctx);

// Traces with the requested backend, printing the choice (and for `auto` why). Throws
// vk::ContextError naming the missing extension when a forced backend is not available.
flow::TraceSet traceWithBackend(const BackendRequest& request, const flow::VectorVolume& volume,
                                std::span<const glm::dvec3> seeds,
                                const flow::TraceOptions& options,
                                const std::function<void(std::size_t)>& progress);

}  // namespace amrstream::cli
