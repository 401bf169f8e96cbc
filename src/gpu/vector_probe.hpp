#pragma once
// Samples of the vector at many points on the device, through the backend's point location and
// the same reconstruction as the tracing kernels (shaders/glsl/include/locate_probe.glsl): what
// pathlines ask of a snapshot at every RK4 stage, since each stage needs two snapshots and the
// host combines them. The points go to the device and the samples come back through host-visible
// buffers, kept for the next call.

#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <span>

#include "../../shaders/glsl/shared/trace_params.h"
#include "backend.hpp"
#include "flow/sampler.hpp"
#include "flow/vector_volume.hpp"
#include "trace_kernel.hpp"
#include "vk/buffer.hpp"
#include "vk/descriptor_pool.hpp"
#include "volume_buffers.hpp"

namespace amrstream::gpu {

// The tracing kernels' bindings (shared/trace_bindings.h) as a probe uses them: `points` (or a
// grid) where the line states are read, `vectors` and `regions` written, `unused` bound for the
// outputs it does not write.
void writeProbeSet(const vk::Context& ctx, VkDescriptorSet set, const VolumeBuffers& device,
                   const vk::Buffer& params, const vk::Buffer& points, const vk::Buffer& vectors,
                   const vk::Buffer& regions, const vk::Buffer& unused);

// The parameters of the probe kernel sampling `volume` at `points` points.
shared::TraceParams probeParams(const flow::VectorVolume& volume, std::size_t points);

// Records the probe kernel over `points` points with `set` bound.
void recordProbe(const vk::Context& ctx, const TraceKernel& kernel, VkCommandBuffer cmd,
                 VkDescriptorSet set, std::size_t points);

class VectorProbe {
 public:
  // The kernel: createTraceKernel(ctx, backend, KernelProgram::LocateProbe), shared by the probes
  // of many volumes. The context, the kernel and `volume` must outlive the probe.
  VectorProbe(const vk::Context& ctx, const TraceKernel& kernel, const flow::VectorVolume& volume);
  // The same on the device copy of `volume` that `device` already holds (it must outlive the
  // probe).
  VectorProbe(const vk::Context& ctx, const TraceKernel& kernel, const flow::VectorVolume& volume,
              const VolumeBuffers& device);

  // flow::sampleVector() at each point (finest-cell units, already wrapped), into `out`, which
  // has one element per point.
  void sample(std::span<const glm::vec3> cellPoints, std::span<flow::VectorSample> out);

  const TracerSetup& setup() const { return setup_; }
  const flow::VectorVolume& volume() const { return *volume_; }
  const VolumeBuffers& device() const { return *device_; }

  // Host time of the calls so far: writing the points, waiting for the device, reading the
  // samples.
  struct Times {
    std::size_t calls = 0;
    double writeSeconds = 0.0, deviceSeconds = 0.0, readSeconds = 0.0;
  };
  const Times& times() const { return times_; }

 private:
  // The parameters' buffer and the one bound where the probe writes nothing.
  void makeFixedBuffers();
  // Host-visible buffers and their descriptor set for `points` points per dispatch.
  void reserve(std::size_t points);
  // Points set_ at the buffers: the points where the tracer reads line states, and unused_ for
  // the outputs the probe does not write.
  void writeSet();

  const vk::Context* ctx_;
  const flow::VectorVolume* volume_;
  TracerSetup setup_;
  std::optional<VolumeBuffers> owned_;
  const VolumeBuffers* device_;
  Times times_;
  const TraceKernel* kernel_;
  std::size_t capacity_ = 0;
  bool clearHints_ = false;  // the regions' buffer is new: its hints are to be cleared first
  vk::Buffer params_, points_, vectors_, regions_, unused_;
  std::unique_ptr<vk::DescriptorPool> pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace amrstream::gpu
