#pragma once
// Runs the benchmark rows: for each backend, one tracer (one Vulkan context, one upload, one
// structure build), a small warm-up trace, then every particle count in every history mode.

#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "bench_types.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream::bench {

// The benchmark on several processes (MPI ranks): each row's particles are shared out, every
// measurement starts together and is combined over the ranks (steps summed, times and device
// memory the largest), so that a row reads as one run on all the ranks' devices.
struct RankShare {
  // This rank's seeds among a row's (indices into them).
  std::function<std::vector<std::uint32_t>(std::span<const glm::dvec3>)> indicesOf;
  std::function<void()> synchronize;
  std::function<double(double)> maxOf, sumOf;
};

struct BenchCallbacks {
  std::function<void(const BackendSetup&)> setupDone;
  std::function<void(const BenchRow&)> rowDone;  // called after the row is in the report
  std::function<void(const std::string&)> note;  // a skipped row or an unavailable backend
  std::optional<RankShare> share;                // none: this process alone
};

// `seeds` holds at least the largest particle count; row n traces its first n seeds. Results are
// appended to `report` (setups, rows, notes).
void runBenchmark(const flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
                  const BenchConfig& config, BenchReport& report,
                  const BenchCallbacks& callbacks = {});

// "AMD EPYC 7763 64-Core Processor, 16 threads", from /proc/cpuinfo and TBB.
std::string hostDescription();

}  // namespace amrstream::bench
