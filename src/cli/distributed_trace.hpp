#pragma once
// `trace` on the ranks of an MPI job, the seeds shared among them (--distribute seeds): every
// rank reads the input and builds the structure, traces its share of the seeds (blocks of their
// Morton order dealt round the ranks) on the GPU its local rank picks. Rank 0 gathers the lines
// and writes them in the order one process would, or (--pieces) every rank writes its own lines
// as one piece and rank 0 a .pvtp listing the pieces. Every phase ends with the ranks agreeing
// on failures, so an error on one rank ends them all with its message, and a failed run leaves
// no piece behind.

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "flow/trace_view.hpp"
#include "mpi/mpi_world.hpp"
#include "output/vtp_writer.hpp"
#include "trace_job.hpp"

namespace amrstream::cli {

struct DistributedOutput {
  std::filesystem::path path;  // the .vtp, or with pieces the .pvtp
  bool pieces = false;
  // Writes traces to one .vtp: the whole on rank 0, or a rank's piece on every rank.
  std::function<output::VtpCounts(const std::filesystem::path&, const flow::TraceView&,
                                  const PreparedInput&)>
      write;
};

// The piece of `rank` beside the .pvtp: traces.pvtp -> traces_0.vtp, traces_1.vtp, ...
std::filesystem::path piecePath(const std::filesystem::path& pvtp, int rank);

// `checkFiles` runs first on every rank (the run's inputs and outputs, RunFiles). With
// `rebalanceSteps` > 0, the ranks trace in rounds of that many steps and even out their live lines
// between rounds, handing lines on; the output is the same.
void traceDistributed(const mpi::MpiWorld& world, TraceJobOptions job, bool keepHistory,
                      std::uint32_t rebalanceSteps, const std::function<void()>& checkFiles,
                      const DistributedOutput& output);

// Collective. Every rank writes `lines` as its piece, rank 0 the .pvtp listing the pieces and
// (after `printSummary`) the summary of every rank's lines; a failure anywhere removes them all.
void writePieces(const mpi::MpiWorld& world, flow::TraceSet lines, PreparedInput& input,
                 const DistributedOutput& output, const std::function<void()>& printSummary);

// "1.2e+04 / 9.9e+03": one value per rank, for the summary lines.
std::string perRank(const std::vector<double>& values, const char* format);

// --distribute: how an MPI job shares the work, seeds or data.
void addDistributeOption(CLI::App& command, std::string& distribute);

}  // namespace amrstream::cli
