#include "api/mpi/rank_rounds.hpp"

#include <fmt/format.h>

#include <utility>

#include "api/device.hpp"
#include "mpi/rank_agreement.hpp"
#include "mpi/run_stitching.hpp"
#include "mpi/trace_exchange.hpp"
#include "util/host_threads.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

void startRankTracer(RankTracer& tracer, PreparedJob::Impl& input, std::size_t lineCount,
                     const Log& log) {
  const BackendChoice choice = chooseBackend(input.backend, BackendUse::Trace, log);
  input.report.backend = gpu::backendName(choice.backend);
  if (choice.backend == gpu::Backend::Cpu) {
    input.report.device = hostThreadsText();
    tracer.advance = mpi::cpuRoundAdvance(input.volume(), input.options);
    return;
  }
  Stopwatch setup;
  tracer.ctx.emplace(createContext(input.backend, choice));
  tracer.gpu.emplace(*tracer.ctx, choice.backend, input.volume(),
                     gpu::runKernelSettings(choice.backend, input.volume(),
                                            std::uint64_t(lineCount) * input.options.maxSteps));
  tracer.gpu->timeKernels(true);
  input.report.device = tracer.ctx->deviceName();
  input.report.setupSeconds = setup.seconds();
  const std::uint64_t slots = tracer.gpu->pointSlots(input.options, lineCount);
  tracer.advance = [&tracer, &input, slots,
                    first = true](std::vector<shared::LineState>& live) mutable {
    const bool order = std::exchange(first, false);
    const std::uint32_t steps =
        flow::stepsPerRound(input.options, slots, live.size() + live.size() / 4);
    return tracer.gpu->advanceRound(live, input.options, steps, order);
  };
}

namespace {

// With pieces, each rank joins and writes a contiguous range of lines, so that the pieces in rank
// order hold the lines in one process's order: the runs go to the rank whose piece holds them.
void writeRunsAsPieces(const MpiWorld& world, flow::TraceSet runs, const flow::LineLayout& layout,
                       PreparedJob::Impl& input, const DistributedOutput& output,
                       const std::function<void()>& sayRanks, const Log& log) {
  const std::size_t lineCount = layout.seedIds.size();
  std::vector<flow::TraceSet> byPiece = mpi::runsByPiece(runs, lineCount, world.size());
  runs = {};
  double bytes = 0.0;
  for (int k = 0; k < world.size(); ++k)
    if (k != world.rank()) bytes += double(mpi::partBytes(byPiece[std::size_t(k)]));
  bytes = world.sumOverRanks(bytes);
  Stopwatch clock;
  std::vector<flow::TraceSet> mine = mpi::agreed(world, [&] {
    std::vector<flow::TraceSet> received;
    for (int k = 0; k < world.size(); ++k) {
      std::vector<flow::TraceSet> parts =
          mpi::gatherTraces(world, std::move(byPiece[std::size_t(k)]), k);
      if (k == world.rank()) received = std::move(parts);
    }
    return received;
  });
  const double exchangeSeconds = world.maxOverRanks(clock.seconds());
  flow::TraceSet lines = mpi::agreed(world, [&] {
    return mpi::stitchRuns(std::move(mine), layout,
                           mpi::pieceLines(lineCount, world.rank(), world.size()));
  });
  writePieces(
      world, std::move(lines), input, output,
      [&] {
        sayRanks();
        say(log, fmt::format("joined     {:.3g} GB of runs sent to the ranks writing their lines "
                             "in {:.2f} s",
                             bytes * 1e-9, exchangeSeconds));
      },
      log);
}

}  // namespace

void writeRankRuns(const MpiWorld& world, flow::TraceSet runs, const flow::LineLayout& layout,
                   PreparedJob::Impl& input, const DistributedOutput& output,
                   const std::function<void()>& sayRanks, const Log& log) {
  if (output.pieces)
    return writeRunsAsPieces(world, std::move(runs), layout, input, output, sayRanks, log);
  const double bytes = world.sumOverRanks(world.isRoot() ? 0.0 : double(mpi::partBytes(runs)));
  Stopwatch clock;
  std::vector<flow::TraceSet> parts =
      mpi::agreed(world, [&] { return mpi::gatherTraces(world, std::move(runs)); });
  const double gatherSeconds = clock.seconds();
  mpi::agreed(world, [&] {
    if (!world.isRoot()) return;
    const flow::TraceSet lines = mpi::stitchRuns(std::move(parts), layout);
    sayRanks();
    say(log,
        fmt::format("gathered   {:.3g} GB to rank 0 in {:.2f} s", bytes * 1e-9, gatherSeconds));
    sayTraceSummary(lines, input.report, log);
    const WrittenLines written =
        writeLines(flow::TraceSetView(lines), output.output, jobProvenance(input));
    say(log, outputLine(output.output.path, written));
  });
}

}  // namespace amrstream
