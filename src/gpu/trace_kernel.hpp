#pragma once
// The tracing-round kernel of one backend: its descriptor set layout (the bindings of
// shaders/glsl/shared/trace_bindings.h), its pipeline layout and pipeline, and for the ray
// tracing pipeline its shader binding table.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>

#include "../../shaders/glsl/shared/trace_bindings.h"
#include "backend.hpp"
#include "flow/trace_options.hpp"
#include "vk/buffer.hpp"
#include "vk/pipelines.hpp"
#include "vk/unique_handle.hpp"

namespace amrstream::vk {
class Context;
}

namespace amrstream::gpu {

using vk::ShaderBindingTable;

struct TraceKernel {
  Backend backend = Backend::Compute;
  VkPipelineBindPoint bindPoint = VK_PIPELINE_BIND_POINT_COMPUTE;
  VkShaderStageFlags stages = 0;
  std::uint32_t workgroupSize = 1;  // compute kernels only
  vk::UniqueHandle<VkDescriptorSetLayout> setLayout;
  vk::UniqueHandle<VkPipelineLayout> pipelineLayout;
  vk::UniqueHandle<VkPipeline> pipeline;
  ShaderBindingTable bindingTable;  // pipeline backend only
};

// Which entry point the kernel runs: the tracer, the point-location probe that tests use to
// compare each backend's locateRegion() with brute force and pathlines sample snapshots with, or
// the grid probe that samples a slice's pixel centres (shaders/glsl/include/locate_probe.glsl).
enum class KernelProgram { Trace, LocateProbe, GridProbe };

// Choices baked into the pipeline through specialization constants.
struct KernelSettings {
  // Samples test the previous sample's region before locating (include/sampler.glsl). The
  // results are the same either way; off, every sample runs the backend's point location.
  bool useRegionHint = true;
  // The step the kernel takes (include/line_round.glsl): one pipeline per integrator.
  flow::Integrator integrator = flow::Integrator::Rk4;
  // Anchors follow the lines (VectorVolume::deepPositions; include/line_round.glsl); off, the
  // anchor stays at zero and the kernel keeps float cell units, as the CPU then does.
  bool deepPositions = false;
  // The tracing kernel reads the vector as dual cells, the 8 values of each 2x2x2 block of a
  // brick together (VolumeBuffers::dualValues), where GpuTracer finds that they fit: the tent
  // interpolant, buffer device addresses, and a quarter of the device's memory. Unset: on GPUs
  // only (on a CPU device such as lavapipe they take host memory, 8 times the values).
  std::optional<bool> dualValues;
  // RK4's samples in one loop instead of written out (include/line_round.glsl): the same sums,
  // one sample's code for the driver to compile instead of four. Unset: on CPU devices, where
  // LLVM spends tens of seconds on the written-out step. The pipeline kernel always loops.
  std::optional<bool> rk4SampleLoop;
  // Rounds of few lines spread them over the subgroups (GpuRounds::spreadLines): at most this
  // many invocations in all. Unset: residentThreads(backend) on GPUs, 0 (one invocation a line)
  // on a CPU device, whose lanes a spread leaves idle.
  std::optional<std::uint32_t> spreadThreads;
};

// About the threads of a backend's tracing kernel that a large GPU keeps resident: 2^17 for the
// compute kernels (an H200's 132 multiprocessors of 32 subgroups: their 64 registers a thread
// allow no more), 2^16 for the ray tracing pipeline. Spread past them, lines of equal length
// run in two waves (docs/benchmarks.md, "A lone line's latency, the spread and the CPU tail").
std::uint32_t residentThreads(Backend backend);

// The settings each backend runs with unless told otherwise: the region hint on everywhere.
KernelSettings defaultKernelSettings(Backend backend);

// Throws std::invalid_argument for Backend::Cpu.
TraceKernel createTraceKernel(const vk::Context& ctx, Backend backend,
                              KernelProgram program = KernelProgram::Trace,
                              const KernelSettings& settings = {});

}  // namespace amrstream::gpu
