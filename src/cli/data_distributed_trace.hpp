#pragma once
// `trace --distribute data` on the ranks of an MPI job (dist/data_rounds.hpp): space cut among
// the ranks by cells, each rank holding the bricks of its part and of a halo, lines handed to the
// rank that owns where they go after every round of a few steps, and rank 0 putting every line
// back together as one polyline and writing the file one process would. On the CPU or any GPU
// backend, each rank on its host's GPU by local rank.

#include <functional>

#include "distributed_trace.hpp"

namespace amrstream::cli {

// `handOffSteps`: steps a line takes between hand-offs; the halo is as wide as they can reach.
void traceOverDataDistributed(const dist::MpiWorld& world, TraceJobOptions job, bool keepHistory,
                              std::uint32_t handOffSteps, const std::function<void()>& checkFiles,
                              const DistributedOutput& output);

}  // namespace amrstream::cli
