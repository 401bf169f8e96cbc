#pragma once
// The trace job over data (--distribute data, mpi/data_rounds.hpp): space cut among the ranks by
// cells, each rank holding the bricks of its part and of a halo, lines handed to the rank that
// owns where they go once they leave the part by more than a margin. Rank 0 puts every line back
// together as one polyline and writes the file one process would; with pieces, every rank does so
// for a contiguous range of the lines. On the CPU or any GPU backend, each rank on its host's GPU
// by local rank.

#include <cstdint>
#include <functional>

#include "api/mpi/seed_distributed_trace.hpp"

namespace amrstream {

// `haloSteps`: the halo is as wide as that many steps reach; lines are handed on once they are
// one step's reach less than that outside the part.
void traceOverData(const MpiWorld& world, TraceJob job, const DistributedOutput& output,
                   std::uint32_t haloSteps, const std::function<void()>& checkFiles,
                   const Reporter& reporter);

}  // namespace amrstream
