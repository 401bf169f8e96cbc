#pragma once
// The trace job on the ranks of an MPI job, one GPU each (by local rank). Over seeds, every rank
// reads the input and traces its share of the seeds (blocks of their Morton order); over data,
// space is cut among the ranks by cells, each holding the bricks of its part and a halo, and
// lines are handed to the rank that owns where they go. Rank 0 gathers the lines and writes the
// file one process would, or (pieces) every rank writes a piece and rank 0 a .pvtp listing them.
// Every phase ends with the ranks agreeing on failures, so an error on one rank ends them all
// with its message (RankFailure), and a failed run leaves no piece behind.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "amrstream/log.hpp"
#include "amrstream/mpi_world.hpp"
#include "amrstream/trace_job.hpp"
#include "amrstream/tracing.hpp"

namespace amrstream {

struct DistributedTrace {
  std::string distribute = "seeds";  // seeds or data
  bool pieces = false;               // each rank writes a piece beside the .pvtp output.path names
  // Over data: the halo reaches this many steps; lines are handed on once they are one step's
  // reach less than that outside the part.
  std::uint32_t haloSteps = 4;
  // Over seeds: trace in rounds of this many steps, evening out the ranks' live lines between
  // them (0: the seeds are split once).
  std::uint32_t rebalanceSteps = 0;
};

// Throws InputError for options that do not go together: a CPU tail with lines that change ranks
// (over data, or rebalanced), rebalancing over data. Front ends call it before choosing between
// one process and traceDistributed, which calls it too.
void checkDistributedTrace(const TraceJob& job, const DistributedTrace& distributed);

// Collective. `checkFiles` runs first on every rank (the run's inputs and outputs, RunFiles).
// Says what `runTraceJob` says, with a "ranks" line of what each rank did, on rank 0.
void traceDistributed(const MpiWorld& world, const TraceJob& job, const TraceOutput& output,
                      const DistributedTrace& distributed, const std::function<void()>& checkFiles,
                      const Reporter& reporter = {});

// The piece of `rank` beside the .pvtp: traces.pvtp -> traces_0.vtp, traces_1.vtp, ...
std::filesystem::path piecePath(const std::filesystem::path& pvtp, int rank);

}  // namespace amrstream
