#pragma once
// Tracing on the chosen backend: the CPU reference or a GPU backend on a Vulkan device.

#include <memory>
#include <span>
#include <string>

#include "amrstream/backend.hpp"
#include "amrstream/log.hpp"
#include "flow/trace_options.hpp"
#include "flow/stored_traces.hpp"
#include "flow/trace_view.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

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

// Traces `seeds` (physical coordinates, inside the domain) with the requested backend, saying on
// `log` what was chosen, the device setup and where a GPU trace's host time went. With
// HostValues::Release and a GPU backend, the volume's values, channel values, gradients and cell
// map are freed once on the device (the CPU path keeps them, and so does a GPU trace with
// options.cpuTailLines, whose last lines the CPU finishes). Throws vk::ContextError naming the
// missing extension when a named backend is not available. The points stay in the rounds that made
// them (StoredTraces::assemble() gives a TraceSet).
flow::StoredTraces trace(const BackendRequest& request, flow::VectorVolume& volume,
                         std::span<const glm::dvec3> seeds, const flow::TraceOptions& options,
                         const flow::TraceProgress& progress = {}, TraceReport* report = nullptr,
                         HostValues hostValues = HostValues::Keep, const Log& log = {});

// Where a GPU trace's points wait until they are written: in host memory, or on the device that
// traced them, copied out as they are written (host memory then holds a few windows of lines
// instead of every point). Auto keeps them on a GPU (not a software device) where they fit.
enum class TraceStore { Auto, Host, Device };

// Traces held for a writer, wherever their points are; a device's traces keep the device open.
class HeldTraces {
 public:
  virtual ~HeldTraces() = default;
  virtual const flow::TraceView& view() const = 0;
};

// As trace(), the points kept where `store` says: on the device where a GPU backend traces and
// TraceStore::Device is asked (or Auto, on a GPU) and every line's maxSteps + 1 points fit (see
// gpu::GpuTracer::traceOnDevice), else in host memory as trace() keeps them. `volume` must
// outlive the result.
std::unique_ptr<HeldTraces> traceForWriting(
    const BackendRequest& request, flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
    const flow::TraceOptions& options, TraceStore store, const flow::TraceProgress& progress = {},
    TraceReport* report = nullptr, HostValues hostValues = HostValues::Keep, const Log& log = {});

// The ReasonForTermination's name, e.g. "out of domain".
const char* reasonName(int reason);

}  // namespace amrstream
