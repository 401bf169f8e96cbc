#pragma once
// `amrstream bench`: the paper's performance experiment. Particle-steps per second of every
// backend over a range of particle counts, with and without history, on one dataset, printed as
// a table and written as JSON. Under MPI every rank runs every row on its share of the particles.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "amrstream/log.hpp"
#include "amrstream/mpi_world.hpp"
#include "amrstream/trace_job.hpp"

namespace amrstream {

struct BenchRequest {
  DatasetRequest dataset;
  std::string vector;  // "a,b,c"; empty: the velocity, else the magnetic field
  std::vector<std::string> backends{"cpu", "rayquery", "pipeline", "compute"};  // in run order
  std::vector<std::size_t> particles;                    // empty: 1024, 2048, ..., 1048576
  std::size_t cpuMaxParticles = 65536;                   // the CPU path skips larger counts
  std::string mode = "both";                             // endpoints, history or both
  std::uint64_t historyPoints = std::uint64_t(1) << 28;  // larger history rows are skipped
  std::uint32_t repeats = 1;                             // each row keeps its fastest
  std::uint32_t steps = 1000;
  std::uint32_t roundSteps = 0;    // 0: as the memory budget allows
  std::uint32_t cpuTailLines = 0;  // GPU rows: the CPU finishes this many last lines
  std::optional<float> stepSize;
  std::string stepMode = "cell";
  std::string interpolant = "tent";
  std::string seedsFile;    // seeds from a file, at least the largest particle count
  std::string seedDensity;  // empty: dens, else the first scalar outside the vector
  double seedPercentile = 90.0;
  std::uint64_t seed = 1;
  std::string device;
  std::string regionHint = "default";  // default, on or off
  std::string dualValues = "default";  // default, on or off
  std::int64_t spreadThreads = -1;     // -1: the default
  std::string seedOrder = "spatial";   // spatial or given
  std::string json = "bench.json";
  std::string commandLine;  // recorded in the JSON
};

// Collective. `checkFiles` runs on every rank after the request's own checks and before any
// work. Says the input, structure, seeds and stepping, then a table row per measurement; rank 0
// writes the JSON after every row.
void runBench(const MpiWorld& world, const BenchRequest& request,
              const std::function<void()>& checkFiles, const Reporter& reporter = {});

}  // namespace amrstream
