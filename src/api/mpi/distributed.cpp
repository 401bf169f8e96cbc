#include "amrstream/distributed.hpp"

#include <fmt/format.h>

#include "amrstream/error.hpp"
#include "api/mpi/data_distributed_trace.hpp"
#include "api/mpi/seed_distributed_trace.hpp"
#include "util/peak_memory.hpp"

namespace amrstream {

std::filesystem::path piecePath(const std::filesystem::path& pvtp, int rank) {
  return pvtp.parent_path() / fmt::format("{}_{}.vtp", pvtp.stem().string(), rank);
}

void checkDistributedTrace(const TraceJob& job, const DistributedTrace& d) {
  if (job.trace.cpuTail > 0 && (d.distribute == "data" || d.rebalanceSteps > 0))
    throw settingError("cpu_tail",
                       "finishes the last lines of one process's trace: not with {distribute} "
                       "data or {rebalance_steps}, which hand lines between ranks");
  if (d.rebalanceSteps > 0 && d.distribute == "data")
    throw settingError("rebalance_steps",
                       "evens out lines among ranks that hold the whole volume: use it with "
                       "{distribute} seeds");
  if (d.distribute != "seeds" && d.distribute != "data")
    throw settingError("distribute", fmt::format("'{}' is not seeds or data", d.distribute));
}

void traceDistributed(const MpiWorld& world, const TraceJob& job, const TraceOutput& output,
                      const DistributedTrace& d, const std::function<void()>& checkFiles,
                      const Reporter& reporter) {
  checkDistributedTrace(job, d);
  const bool stagePeak = resetStagePeak();
  const DistributedOutput written{output, d.pieces};
  if (d.distribute == "data")
    traceOverData(world, job, written, d.haloSteps, checkFiles, reporter);
  else
    traceOverSeeds(world, job, written, d.rebalanceSteps, checkFiles, reporter);
  say(reporter.log, memoryLine(stagePeak));
}

}  // namespace amrstream
