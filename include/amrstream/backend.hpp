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

// What the backend is for: tracing alone may fall back to the CPU reference, rendering needs a
// Vulkan device.
enum class BackendUse { Trace, Render };

// Resolves `auto` (printing what was chosen and why) or parses the named backend. For tracing,
// `auto` picks the fastest: a GPU backend on a GPU, the CPU reference when the only Vulkan
// device is a software one (lavapipe), which traces several times slower than the CPU path.
BackendChoice chooseBackend(const BackendRequest& request, BackendUse use = BackendUse::Render);

// A context for the choice's backend and device, plus `extra` capabilities. Throws
// vk::ContextError naming what is missing.
vk::Context createContext(const BackendRequest& request, const BackendChoice& choice,
                          vk::CapabilitySet extra = {});

// Throws when the context's validation layer reported errors.
void checkValidation(const vk::Context& ctx);

// What ran a trace and where its time went: creating the device context, uploading the volume
// and building its point-location structure and kernels (0 on the CPU), then tracing proper.
struct TraceReport {
  std::string backend;  // "compute", "cpu", ...
  std::string device;   // the Vulkan device's name, or the CPU's thread count
  double setupSeconds = 0.0;
  double traceSeconds = 0.0;
};

// What happens to the volume's host copy of its values once a GPU backend has uploaded them.
enum class HostValues { Keep, Release };

// Traces with the requested backend, printing the choice (and for `auto` why). With
// HostValues::Release and a GPU backend, the volume's values, channel values and cell map are
// freed once on the device (the CPU path keeps them). Throws vk::ContextError naming the missing
// extension when a forced backend is not available.
flow::StoredTraces traceWithBackend(const BackendRequest& request, flow::VectorVolume& volume,
                                    std::span<const glm::dvec3> seeds,
                                    const flow::TraceOptions& options,
                                    const flow::TraceProgress& progress,
                                    TraceReport* report = nullptr,
                                    HostValues hostValues = HostValues::Keep);

}  // namespace amrstream::cli
