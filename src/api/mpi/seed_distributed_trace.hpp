#pragma once
// The trace job over seeds (--distribute seeds): every rank reads the input and builds the
// structure, traces its share of the seeds (blocks of their Morton order dealt round the ranks)
// on the GPU its local rank picks. Rank 0 gathers the lines and writes them in the order one
// process would, or (pieces) every rank writes its own lines as one piece and rank 0 a .pvtp
// listing the pieces.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "amrstream/mpi_world.hpp"
#include "amrstream/trace_job.hpp"
#include "api/job_state.hpp"

namespace amrstream {

struct DistributedOutput {
  TraceOutput output;  // the .vtp, or with pieces the .pvtp
  bool pieces = false;
};

// `checkFiles` runs first on every rank. With `rebalanceSteps` > 0, the ranks trace in rounds of
// that many steps and even out their live lines between rounds, handing lines on; the output is
// the same.
void traceOverSeeds(const MpiWorld& world, TraceJob job, const DistributedOutput& output,
                    std::uint32_t rebalanceSteps, const std::function<void()>& checkFiles,
                    const Reporter& reporter);

// Collective. Every rank writes `lines` as its piece, rank 0 the .pvtp listing the pieces and
// (after `saySummary`) the summary of every rank's lines; a failure anywhere removes them all.
void writePieces(const MpiWorld& world, flow::TraceSet lines, PreparedJob::Impl& input,
                 const DistributedOutput& output, const std::function<void()>& saySummary,
                 const Log& log);

// "1.2e+04 / 9.9e+03": one value per rank, for the summary lines.
std::string perRank(const std::vector<double>& values, const char* format);

}  // namespace amrstream
