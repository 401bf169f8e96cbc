#pragma once
// Tracing seeds through a volume on the requested backend (the CPU reference or a GPU backend on
// a Vulkan device), the points held where a writer reads them.

#include <memory>
#include <span>

#include "amrstream/backend.hpp"
#include "amrstream/log.hpp"
#include "amrstream/trace_job.hpp"
#include "amrstream/tracing.hpp"
#include "api/device_opening.hpp"
#include "flow/stored_traces.hpp"
#include "flow/trace_options.hpp"
#include "flow/trace_view.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

// Traces held for a writer, wherever their points are; a device's traces keep the device open.
class HeldTraces {
 public:
  virtual ~HeldTraces() = default;
  virtual const flow::TraceView& view() const = 0;
  // The points in host memory, line after line; only traces held in host memory have them.
  virtual flow::TraceSet assemble() && = 0;
};

// Traces `seeds` (physical coordinates, inside the domain) with the requested backend, saying on
// `log` what was chosen, the device setup and where a GPU trace's host time went. With
// HostValues::Release and a GPU backend, the volume's values, channel values, gradients and cell
// map are freed once on the device (the CPU path keeps them, and so does a GPU trace with
// options.cpuTailLines, whose last lines the CPU finishes). Throws vk::ContextError naming the
// missing extension when a named backend is not available. The points stay in the rounds that
// made them (StoredTraces::assemble() gives a TraceSet).
flow::StoredTraces traceSeeds(const BackendRequest& request, flow::VectorVolume& volume,
                              std::span<const glm::dvec3> seeds, const flow::TraceOptions& options,
                              const flow::TraceProgress& progress = {},
                              TraceReport* report = nullptr,
                              HostValues hostValues = HostValues::Keep, const Log& log = {});

// As traceSeeds(), the points kept where `store` says: on the device where a GPU backend traces
// and TraceStore::Device is asked (or Auto, on a GPU) and every line's maxSteps + 1 points fit,
// else in host memory. `volume` must outlive the result. With `opening`, the backend and its
// device are those it opened for `request`.
std::unique_ptr<HeldTraces> traceForWriting(
    const BackendRequest& request, flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
    const flow::TraceOptions& options, TraceStore store, const flow::TraceProgress& progress = {},
    TraceReport* report = nullptr, HostValues hostValues = HostValues::Keep, const Log& log = {},
    DeviceOpening* opening = nullptr);

}  // namespace amrstream
