#pragma once
// What `amrstream bench` measures: one row per (backend, history mode, particle count), plus
// the cost of building the structures each row relies on.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "flow/trace_options.hpp"

namespace amrstream::bench {

struct BenchConfig {
  std::vector<std::string> backends;            // cpu, rayquery, pipeline, compute, in run order
  std::vector<std::size_t> particles;           // counts, ascending; rows use a prefix of the seeds
  std::size_t cpuMaxParticles = 65536;          // the CPU path skips larger counts
  std::vector<bool> historyModes{false, true};  // false: endpoints only; true: every step
  std::uint64_t historyPointBudget = std::uint64_t(1) << 28;  // larger history rows are skipped
  std::uint32_t repeats = 1;                                  // each row keeps its fastest repeat
  flow::TraceOptions trace;                                   // keepHistory is set per row
  std::optional<bool> regionHint;  // GPU kernels test the previous region first; none:
                                   // each backend's default (gpu::defaultKernelSettings)
  std::optional<bool> dualValues;  // GPU kernels read dual cells; none: the default
  std::optional<std::uint32_t> spreadThreads;  // gpu::KernelSettings::spreadThreads; none: default
  bool spatialSeedOrder = true;                // GPU threads take seeds in Morton order (GpuTracer)
  std::string deviceFilter;                    // a substring of the Vulkan device's name
  unsigned deviceSlot = 0;                     // which qualifying device (vk::ContextBuilder)
  bool validation = false;
};

struct BenchRow {
  std::string backend;
  std::string device;
  bool history = false;
  std::size_t particles = 0;
  std::uint32_t maxSteps = 0;
  std::uint64_t steps = 0;                  // particle-steps taken, summed over the traces
  std::optional<double> kernelSeconds;      // GPU: timestamp queries around the tracing kernel
  std::optional<double> compactionSeconds;  // GPU: the same around compaction and point data
  double wallSeconds = 0.0;                 // the whole trace call: uploads, rounds, read-back
  std::uint64_t deviceBytes = 0;            // GPU: volume + structure + the largest batch's buffers
  std::size_t chunks = 0;                   // GPU: batches of lines
  std::size_t rounds = 0;                   // GPU: rounds of steps, over all batches
  // GPU with trace.cpuTailLines: the lines the CPU reference finished, its steps for them, and
  // its wall time (part of wallSeconds).
  std::size_t tailLines = 0;
  std::uint64_t tailSteps = 0;
  double tailSeconds = 0.0;

  // Kernel time where there is one and the GPU took every step, else wall time.
  double stepsPerSecond() const;
  double wallStepsPerSecond() const;
};

// The setup of one backend: its device and what building the tracer took.
struct BackendSetup {
  std::string backend;
  std::string device;
  std::string driver;
  double contextSeconds = 0.0;
  double uploadSeconds = 0.0;
  double structureSeconds = 0.0;  // region tree upload, or acceleration structure build
  double pipelineSeconds = 0.0;
  bool regionHint = false;
  bool dualValues = false;
  std::uint32_t spreadThreads = 0;
  std::uint64_t volumeBytes = 0;
  std::uint64_t structureBytes = 0;
};

// The dataset and the host-side structures.
struct DatasetStats {
  std::string source;
  std::size_t cells = 0;
  int finestLevel = 0, coarsestLevel = 0;
  std::string vector;
  double loadSeconds = 0.0;  // read or generate, including the AMR model's validation
  std::size_t bricks = 0, regions = 0;
  double bricksSeconds = 0.0, regionsSeconds = 0.0, gatherSeconds = 0.0;
  std::string seeding;
};

struct BenchReport {
  DatasetStats dataset;
  std::string host;  // CPU model and thread count
  int ranks = 1;     // MPI ranks, each on its own device where the host has several
  std::string command;
  BenchConfig config;
  std::vector<BackendSetup> setups;
  std::vector<BenchRow> rows;
  std::vector<std::string> notes;  // skipped rows, unavailable backends
};

}  // namespace amrstream::bench
