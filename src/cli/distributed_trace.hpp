#pragma once
// `trace` on the ranks of an MPI job, the seeds shared among them (--distribute seeds): every
// rank reads the input and builds the structure, traces one contiguous range of the seeds' Morton
// order on the GPU its local rank picks, and rank 0 gathers the lines and writes them in the
// order one process would. Every phase ends with the ranks agreeing on failures, so an error on
// one rank ends them all with its message.

#include <functional>

#include "dist/mpi_world.hpp"
#include "flow/trace_view.hpp"
#include "trace_job.hpp"

namespace amrstream::cli {

// Writes the gathered traces; called on rank 0 only.
using TracesWriter = std::function<void(const flow::TraceView& traces, PreparedInput& input)>;

// `checkFiles` runs first on every rank (the run's inputs and outputs, RunFiles).
void traceDistributed(const dist::MpiWorld& world, TraceJobOptions job, bool keepHistory,
                      const std::function<void()>& checkFiles, const TracesWriter& write);

// --distribute: how an MPI job shares the work (only `seeds` exists).
void addDistributeOption(CLI::App& command, std::string& distribute);
// Refuses a mode that does not exist yet, naming the option.
void checkDistributeOption(const std::string& distribute);

}  // namespace amrstream::cli
