#include "data_distributed_trace.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <utility>

#include "amrstream/backend.hpp"
#include "dist/data_partition.hpp"
#include "dist/data_rounds.hpp"
#include "dist/rank_agreement.hpp"
#include "dist/run_stitching.hpp"
#include "dist/trace_exchange.hpp"
#include "flow/line_plan.hpp"
#include "gpu/gpu_tracer.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

void checkDataVolume(const flow::VectorVolume& volume) {
  if (volume.deepPositions())
    throw InputError("--distribute data",
                     "is not available for domains wider than 2^21 finest cells");
}

struct RankPart {
  PreparedInput input;
  dist::DataPartition partition;
  flow::LinePlan plan;
  double halo = 0.0;  // finest cells
  std::size_t allBricks = 0;
};

RankPart prepareRank(const dist::MpiWorld& world, const TraceJobOptions& job, bool keepHistory,
                     std::uint32_t haloSteps) {
  RankPart rank;
  PreparedInput& input = rank.input;
  input = prepareInput(job);
  checkDataVolume(input.volume);
  input.options.keepHistory = keepHistory;
  const bricks::AmrField& cells = input.field();
  float widest = 0.0f;
  for (const shared::Region& region : input.volume.regions.regions)
    widest = std::max(widest, region.finestCellWidth);
  // A step's stages from anywhere lines stay before they are handed on (the part and a margin),
  // or from the domain's padding next to it.
  const dist::StepReach reach = dist::stepReach(input.volume, input.options);
  const double margin = (haloSteps - 1) * reach.step * 1.01;
  rank.halo = margin + reach.stage * 1.01 + 0.5 * widest + 2.0;
  // The linear interpolant's gradients at the cells samples reach fit their face neighbours.
  const double kept =
      rank.halo + (input.volume.interpolant == flow::Interpolant::Linear ? 2.0 * widest : 0.0);
  rank.partition = dist::partitionCells(cells, world.size(), rank.halo);
  // The parts in the volume's cell units: buildCellLayout centres cells that lie far from the
  // origin.
  const glm::ivec3 shift = input.volume.domain.lower - cells.bounds().lower;
  for (std::size_t k = 0; k < rank.partition.lower.size(); ++k) {
    rank.partition.lower[k] += shift;
    rank.partition.upper[k] += shift;
  }
  input.options.pauseOutside =
      dist::pauseBox(rank.partition, world.rank(), margin, input.volume.periodic);
  rank.plan = flow::planLines(input.volume, input.seeds.points, input.options.direction);
  rank.allBricks = input.volume.bricks.size();

  const glm::ivec3 lower = rank.partition.lower[std::size_t(world.rank())];
  const glm::ivec3 upper = rank.partition.upper[std::size_t(world.rank())];
  flow::VolumeOptions part;  // as the whole volume's (api/field.cpp), cropped
  part.pointData = input.volume.channelNames;
  part.periodic = input.volume.periodic;
  part.interpolant = input.volume.interpolant;
  part.keepAround = flow::VolumeOptions::Box{glm::dvec3(lower) - kept, glm::dvec3(upper) + kept};
  input.volume = flow::buildVectorVolume(
      cells, flow::chooseVectorChannels(cells, job.field.vector), part);
  input.releaseField();
  return rank;
}

}  // namespace

void traceOverDataDistributed(const dist::MpiWorld& world, TraceJobOptions job, bool keepHistory,
                              std::uint32_t haloSteps, const std::function<void()>& checkFiles,
                              const DistributedOutput& output) {
  if (!world.isRoot()) job.seedsOut.clear();  // rank 0 writes it
  RankPart rank = dist::agreed(world, [&] {
    checkFiles();
    return prepareRank(world, job, keepHistory, haloSteps);
  });
  PreparedInput& input = rank.input;

  std::vector<shared::LineState> owned;
  for (const shared::LineState& s : rank.plan.states)
    if (rank.partition.ownerOf(dist::cellPointOf(s)) == world.rank()) owned.push_back(s);
  const double ownedLines = double(owned.size());

  // The backend, its device and its tracer for this rank's part.
  job.backend.deviceSlot = unsigned(world.localRank());
  std::optional<vk::Context> ctx;
  std::optional<gpu::GpuTracer> gpuTracer;
  dist::RoundAdvance advance = dist::agreed(world, [&] {
    const BackendChoice choice = chooseBackend(job.backend, BackendUse::Trace, printLine);
    input.report.backend = gpu::backendName(choice.backend);
    if (choice.backend == gpu::Backend::Cpu) {
      input.report.device = "cpu";
      return dist::cpuRoundAdvance(input.volume, input.options);
    }
    Stopwatch setup;
    ctx.emplace(createContext(job.backend, choice));
    gpuTracer.emplace(*ctx, choice.backend, input.volume);
    gpuTracer->timeKernels(true);
    input.report.device = ctx->deviceName();
    input.report.setupSeconds = setup.seconds();
    // The lines are put in Morton order once; later rounds keep their order, the lines handed
    // on from other ranks coming after them. The rounds share output slots as one process's
    // rounds do, with room for a quarter more lines handed on.
    const std::uint64_t slots = gpuTracer->pointSlots(input.options, rank.plan.states.size());
    auto round = [&, slots, first = true](std::vector<shared::LineState>& live) mutable {
      const bool order = std::exchange(first, false);
      const std::uint32_t steps =
          flow::stepsPerRound(input.options, slots, live.size() + live.size() / 4);
      return gpuTracer->advanceRound(live, input.options, steps, order);
    };
    return dist::RoundAdvance(round);
  });

  // Rounds exchange lines and sum the live ones: a failure inside ends every rank (main).
  dist::DataRoundStats stats;
  Stopwatch clock;
  flow::TraceSet runs = dist::traceOverData(world, input.volume, rank.partition, std::move(owned),
                                            input.options, advance, &stats);
  const double seconds = clock.seconds();
  dist::agreed(world, [&] {
    if (ctx) checkValidation(*ctx);
  });
  const double deviceBytes =
      gpuTracer ? double(gpuTracer->setup().volumeBytes + gpuTracer->setup().structureBytes +
                         gpuTracer->lastRun().roundBytes)
                : 0.0;
  const std::vector<double> rankDevice = world.gatherToRoot(deviceBytes / 0x1p20);
  input.report.traceSeconds = world.maxOverRanks(seconds);
  input.report.setupSeconds = world.maxOverRanks(input.report.setupSeconds);
  const std::vector<double> rankBricks = world.gatherToRoot(double(input.volume.bricks.size()));
  const std::vector<double> rankLines = world.gatherToRoot(ownedLines);
  const std::vector<double> rankCells = world.gatherToRoot(double(input.volume.values.size()));
  const std::vector<double> rankSent = world.gatherToRoot(double(stats.linesSent));
  const std::vector<double> rankTracing = world.gatherToRoot(stats.traceSeconds);
  const std::vector<double> rankExchange = world.gatherToRoot(stats.exchangeSeconds);
  const double handOffs = world.sumOverRanks(double(stats.linesSent));
  const auto printRanks = [&] {
    fmt::print("ranks      {} over data: bricks held {} of {} (cropped to the part and a halo of "
               "{:.0f} finest cells), cells {}, lines starting {}, rounds {}, "
               "hand-offs {} ({:.3g} MB), tracing {} s, handing on {} s\n",
               world.size(), perRank(rankBricks, "{:.0f}"), rank.allBricks, rank.halo,
               perRank(rankCells, "{:.3g}"), perRank(rankLines, "{:.0f}"), stats.rounds,
               perRank(rankSent, "{:.0f}"), handOffs * sizeof(shared::LineState) * 1e-6,
               perRank(rankTracing, "{:.3f}"), perRank(rankExchange, "{:.3f}"));
    if (gpuTracer) {
      fmt::print("device     MiB per rank (volume, structure, rounds): {}\n",
                 perRank(rankDevice, "{:.1f}"));
      const gpu::TraceRunStats& r = gpuTracer->lastRun();
      fmt::print("rounds     rank 0, {} rounds: kernel {:.3f} s, ordering and uploading lines "
                 "{:.3f} s, submitting {:.3f} s, waiting for rounds {:.3f} s and copies {:.3f} s, "
                 "unpacking {:.3f} s, reading states back {:.3f} s\n",
                 r.rounds, r.kernelSeconds.value_or(0.0), r.linesSeconds, r.submitSeconds,
                 r.roundWaitSeconds, r.copyWaitSeconds, r.unpackSeconds, r.statesSeconds);
    }
  };

  if (output.pieces) {
    // Each rank joins and writes a contiguous range of lines, so that the pieces in rank order
    // hold the lines in one process's order: the runs go to the rank whose piece holds them.
    const std::size_t lineCount = rank.plan.states.size();
    std::vector<flow::TraceSet> byPiece = dist::runsByPiece(runs, lineCount, world.size());
    runs = {};
    double bytes = 0.0;
    for (int k = 0; k < world.size(); ++k)
      if (k != world.rank()) bytes += double(dist::partBytes(byPiece[std::size_t(k)]));
    bytes = world.sumOverRanks(bytes);
    clock.restart();
    std::vector<flow::TraceSet> mine = dist::agreed(world, [&] {
      std::vector<flow::TraceSet> received;
      for (int k = 0; k < world.size(); ++k) {
        std::vector<flow::TraceSet> parts =
            dist::gatherTraces(world, std::move(byPiece[std::size_t(k)]), k);
        if (k == world.rank()) received = std::move(parts);
      }
      return received;
    });
    const double exchangeSeconds = world.maxOverRanks(clock.seconds());
    flow::TraceSet lines = dist::agreed(world, [&] {
      return dist::stitchRuns(std::move(mine), rank.plan.layout,
                              dist::pieceLines(lineCount, world.rank(), world.size()));
    });
    writePieces(world, std::move(lines), input, output, [&] {
      printRanks();
      fmt::print("joined     {:.3g} GB of runs sent to the ranks writing their lines in {:.2f} s\n",
                 bytes * 1e-9, exchangeSeconds);
    });
    return;
  }

  const double bytes = world.sumOverRanks(world.isRoot() ? 0.0 : double(dist::partBytes(runs)));
  clock.restart();
  std::vector<flow::TraceSet> parts =
      dist::agreed(world, [&] { return dist::gatherTraces(world, std::move(runs)); });
  const double gatherSeconds = clock.seconds();
  dist::agreed(world, [&] {
    if (!world.isRoot()) return;
    const flow::TraceSet lines = dist::stitchRuns(std::move(parts), rank.plan.layout);
    printRanks();
    fmt::print("gathered   {:.3g} GB to rank 0 in {:.2f} s\n", bytes * 1e-9, gatherSeconds);
    printTraceSummary(lines, input.report);
    clock.restart();
    const output::VtpCounts counts = output.write(output.path, flow::TraceSetView(lines), input);
    fmt::print("output     {} ({} polylines, {} points) [{:.2f} s]\n", output.path.string(),
               withCommas(counts.lines), withCommas(counts.points), clock.seconds());
  });
}

}  // namespace amrstream::cli
