#pragma once
// Streamline tracing on a Vulkan device with one of the GPU backends. Owns the volume's device
// buffers (bricks, values, regions, region bricks), the backend's point-location structure (the
// region tree for `compute`, an AABB acceleration structure for `rayquery` and `pipeline`) and
// the kernel; trace() may be called many times.
//
// Runs proceed in chunks of seeds so that no output array passes maxStorageBufferRange or a
// quarter of the device's largest memory heap; the results are those of one run.

#include <cstddef>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "backend.hpp"
#include "flow/integrator.hpp"
#include "flow/trace_set.hpp"
#include "flow/vector_volume.hpp"
#include "trace_kernel.hpp"
#include "vk/aabb_scene.hpp"
#include "vk/buffer.hpp"
#include "vk/gpu_timer.hpp"

namespace amrstream::gpu {

// What constructing the tracer took.
struct TracerSetup {
  double uploadSeconds = 0.0;     // the volume's buffers to the device
  double structureSeconds = 0.0;  // the region tree's upload, or the acceleration structure build
  double pipelineSeconds = 0.0;   // shader modules and pipeline (and binding table)
  std::uint64_t volumeBytes = 0;     // device bytes of bricks, values, regions and region bricks
  std::uint64_t structureBytes = 0;  // device bytes of the region tree or of the BLASes and TLAS
};

// The dispatches of the last trace().
struct TraceRunStats {
  std::optional<double> kernelSeconds;  // device time summed over chunks; none without timestamps
  std::size_t chunks = 0;
  std::uint64_t chunkBytes = 0;  // device bytes of the largest chunk's seeds and outputs
};

class GpuTracer {
 public:
  // The context must have requiredCapabilities(backend) and outlive the tracer; `volume` must
  // outlive it too.
  GpuTracer(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume);
  GpuTracer(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume,
            const KernelSettings& settings);

  // Seeds in physical coordinates, as flow::traceStreamlines; the same output layout.
  // `progress` is called with the number of seeds finished after each chunk.
  flow::TraceSet trace(std::span<const glm::dvec3> seeds, const flow::TraceOptions& options,
                       const std::function<void(std::size_t)>& progress = {});

  // The backend's locateRegion() for points in finest-cell units: the region id, or -1 outside
  // the domain and in empty space. Used by tests to compare point location with brute force.
  std::vector<std::int32_t> locate(std::span<const glm::vec3> cellPoints);

  Backend backend() const { return kernel_.backend; }
  const TracerSetup& setup() const { return setup_; }
  const TraceRunStats& lastRun() const { return lastRun_; }
  // Seeds per dispatch for traces of `capacity` points.
  std::size_t seedsPerChunk(std::uint32_t capacity) const;
  // Caps the seeds per dispatch (0: no cap), so that tests can run many chunks on small inputs.
  void limitSeedsPerChunk(std::size_t limit) { chunkLimit_ = limit; }
  // On (the default), each dispatch hands seeds to threads in Morton order of their positions,
  // so that a subgroup traces neighbouring seeds through the same bricks; results are returned
  // in the caller's order either way.
  void orderSeedsSpatially(bool on) { spatialOrder_ = on; }

 private:
  // Output buffers of one dispatch, in binding order (positions, times, vectors, point counts,
  // reasons).
  struct Outputs {
    vk::Buffer positions, times, vectors, pointCounts, reasons;
  };
  Outputs makeOutputs(std::size_t seeds, std::uint32_t capacity) const;
  // Runs the kernel over the seeds; returns its device time when the device has timestamps.
  std::optional<double> dispatch(const TraceKernel& kernel, const shared::TraceParams& params,
                                 std::span<const glm::vec3> seedCells,
                                 const Outputs& outputs) const;
  void traceChunk(std::span<const glm::dvec3> seeds, const flow::TraceOptions& options,
                  flow::TraceSet& out, std::uint32_t firstSeed);

  const vk::Context* ctx_;
  const flow::VectorVolume* volume_;
  vk::Buffer bricks_;
  vk::Buffer values_;
  vk::Buffer regions_;
  vk::Buffer regionBricks_;
  vk::Buffer tree_;                     // compute backend
  std::optional<vk::AabbScene> scene_;  // rayquery and pipeline backends
  TraceKernel kernel_;
  std::optional<TraceKernel> probe_;  // created by the first locate()
  vk::GpuTimer timer_;
  std::size_t chunkLimit_ = 0;
  bool spatialOrder_ = true;
  TracerSetup setup_;
  TraceRunStats lastRun_;
};

}  // namespace amrstream::gpu
