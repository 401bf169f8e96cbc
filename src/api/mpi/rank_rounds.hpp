#pragma once
// What the MPI traces that move lines between ranks (over data, and over seeds with re-splits)
// share: each rank's tracer, run round by round, and putting the ranks' runs of every line
// together as one process's lines to write them.

#include <functional>
#include <optional>

#include "amrstream/mpi_world.hpp"
#include "api/job_state.hpp"
#include "api/mpi/seed_distributed_trace.hpp"
#include "flow/line_plan.hpp"
#include "gpu/gpu_tracer.hpp"
#include "mpi/data_rounds.hpp"
#include "vk/context.hpp"

namespace amrstream {

// A rank's backend and its rounds. Stays where it is made: `advance` refers to the others.
struct RankTracer {
  std::optional<vk::Context> ctx;
  std::optional<gpu::GpuTracer> gpu;  // none on the CPU backend
  mpi::RoundAdvance advance;
};

// Picks the backend for the rank (its local rank's GPU) and readies `tracer` to advance up to
// `lineCount` lines of `input` (whose report gets the backend, device and setup seconds). On a
// GPU the lines are put in Morton order once; later rounds keep their order, lines from other
// ranks coming after them, and share output slots with room for a quarter more lines.
void startRankTracer(RankTracer& tracer, PreparedJob::Impl& input, std::size_t lineCount,
                     const Log& log);

// Collective. Puts every line back together from the ranks' runs (mpi::stitchRuns) and writes
// them: rank 0 the whole .vtp after `sayRanks`, or with pieces every rank a contiguous range of
// the lines.
void writeRankRuns(const MpiWorld& world, flow::TraceSet runs, const flow::LineLayout& layout,
                   PreparedJob::Impl& input, const DistributedOutput& output,
                   const std::function<void()>& sayRanks, const Log& log);

}  // namespace amrstream
