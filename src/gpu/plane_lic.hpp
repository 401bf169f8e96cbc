#pragma once
// A slice's LIC on the device: the vector sampled at the plane's pixel centres by the backend's
// point location and reconstruction (the grid probe, shaders/glsl/include/locate_probe.glsl),
// then convolved by shaders/glsl/lic.comp, the twin of slice::lineIntegralConvolution. The
// samples stay on the device; the intensities come back.

#include <vector>

#include "../../shaders/glsl/shared/plane_lic.h"
#include "backend.hpp"
#include "flow/vector_volume.hpp"
#include "trace_kernel.hpp"
#include "vk/buffer.hpp"
#include "vk/descriptor_pool.hpp"
#include "volume_buffers.hpp"

namespace amrstream::gpu {

class PlaneLic {
 public:
  // Uploads `volume` for `backend` (not Backend::Cpu) and makes the kernels. The context and
  // `volume` must outlive it.
  PlaneLic(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume);

  // The LIC intensity at every point of `grid` (slice::pixelGrid: x fastest; NaN where the
  // plane has no data), with params.width and params.height those of the grid.
  std::vector<float> convolve(const shared::ProbeGrid& grid, const shared::LicParams& params);

  const TracerSetup& setup() const { return setup_; }
  struct Times {
    double deviceSeconds = 0.0;  // sampling and convolving, on the device
    double readSeconds = 0.0;    // the intensities to the host
  };
  const Times& times() const { return times_; }

 private:
  void reserve(std::size_t pixels);

  const vk::Context* ctx_;
  const flow::VectorVolume* volume_;
  TracerSetup setup_;
  VolumeBuffers device_;
  TraceKernel probe_;
  vk::UniqueHandle<VkDescriptorSetLayout> licSetLayout_;
  vk::UniqueHandle<VkPipelineLayout> licLayout_;
  vk::UniqueHandle<VkPipeline> lic_;
  vk::Buffer params_, grid_, unused_, vectors_, intensity_;
  std::size_t capacity_ = 0;
  std::unique_ptr<vk::DescriptorPool> pool_;
  VkDescriptorSet probeSet_ = VK_NULL_HANDLE, licSet_ = VK_NULL_HANDLE;
  Times times_;
};

}  // namespace amrstream::gpu
