#include "api/mpi/data_distributed_trace.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <utility>

#include "amrstream/error.hpp"
#include "api/device.hpp"
#include "api/field_plan.hpp"
#include "api/frame_choice.hpp"
#include "api/input_share.hpp"
#include "api/mpi/rank_rounds.hpp"
#include "api/stepping.hpp"
#include "flow/gradient_request.hpp"
#include "flow/line_plan.hpp"
#include "formats/load_input.hpp"
#include "gpu/gpu_tracer.hpp"
#include "mpi/data_partition.hpp"
#include "mpi/data_rounds.hpp"
#include "mpi/rank_agreement.hpp"
#include "mpi/value_windows.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

namespace {

void checkDataVolume(const flow::VectorVolume& volume) {
  if (volume.deepPositions())
    throw settingError("distribute",
                       "data is not available for domains wider than 2^21 finest cells");
}

struct RankPart {
  std::optional<PreparedJob> prepared;
  mpi::DataPartition partition;
  flow::LinePlan plan;
  double halo = 0.0;  // finest cells
  std::size_t allBricks = 0;
  formats::WindowedRead read;  // pieces 0: the whole input was read
};

// How far a rank's lines go past its part before they are handed on (margin), how far their
// samples reach (halo) and the cells it keeps for them (kept), in finest cells.
struct RankReach {
  double margin = 0.0, halo = 0.0, kept = 0.0;
};

// `fastest`: the fastest vector, when the volume holds part of the values.
RankReach rankReach(const flow::VectorVolume& volume, const flow::VectorChannels& vector,
                    const flow::TraceOptions& options, std::uint32_t haloSteps,
                    std::optional<double> fastest = std::nullopt) {
  float widest = 0.0f;
  for (const shared::Region& region : volume.regions.regions)
    widest = std::max(widest, region.finestCellWidth);
  // A step's stages from anywhere lines stay before they are handed on (the part and a margin),
  // or from the domain's padding next to it.
  const mpi::StepReach reach = mpi::stepReach(volume, options, fastest);
  RankReach r;
  r.margin = (haloSteps - 1) * reach.step * 1.01;
  r.halo = r.margin + reach.stage * 1.01 + 0.5 * widest + 2.0;
  // Gradients fitted to face neighbours (the linear interpolant's, a gradient vector's, and
  // with both the gradients of the gradient) at the cells samples reach fit every neighbour.
  const int fits =
      (volume.interpolant == flow::Interpolant::Linear ? 1 : 0) + (vector.isGradient() ? 1 : 0);
  r.kept = r.halo + 2.0 * widest * fits;
  return r;
}

// Over data, a rank reads the values of its part and what it keeps around it alone where the
// format allows, in arc mode (a step's reach follows from the cells' layout) and in cell mode
// with the tent interpolant (it also needs the fastest cell, which the ranks find together); in
// time mode the default step depends on the fastest vector too, and the linear interpolant's
// reach on its steepest gradient. A gradient vector's values at a part's edge come from cells
// beyond it, and frame_velocity auto's mean from the whole seeding region: with either, every
// rank reads the whole input.
bool readsItsPartAlone(const TraceJob& job) {
  return formats::readsValueWindows(formats::detectFormat(job.dataset.input)) &&
         (job.trace.stepMode == "arc" ||
          (job.trace.stepMode == "cell" && job.field.interpolant == "tent")) &&
         !flow::parseGradientRequest(job.field.vector) &&
         !parseFrameVelocity(job.field.frameVelocity).automatic;
}

// The fastest vector of the whole input: each rank reads its part of a first cut alone.
double fastestOverRanks(const MpiWorld& world, const TraceJob& job,
                        const bricks::AmrField& layoutCells) {
  const mpi::DataPartition first = mpi::partitionCells(layoutCells, world.size(), 0.0);
  const formats::ValueWindow window =
      mpi::partWindow(first, world.rank(), 0.0, layoutCells.bounds(), {});
  // Agreed before the collective: a rank that fails to read ends every rank.
  const double mine = mpi::agreed(world, [&] {
    const bricks::AmrField part =
        formats::loadInput(job.dataset.input, job.dataset.builtin, &window);
    const flow::VectorChannels vector = flow::chooseVectorChannels(part, job.field.vector);
    const std::vector<float>& x = part.channel(vector.channels[0]).values;
    const std::vector<float>& y = part.channel(vector.channels[1]).values;
    // A 2D dataset's vector has no third channel: zeros.
    const std::vector<float> zeros(vector.channels[2].empty() ? x.size() : 0, 0.0f);
    const std::vector<float>& z =
        vector.channels[2].empty() ? zeros : part.channel(vector.channels[2]).values;
    const glm::dvec3 frame = parseFrameVelocity(job.field.frameVelocity).velocity;
    double fastest = 0.0;  // as stepReach finds it over a whole volume's values
    for (std::size_t c = 0; c < x.size(); ++c)
      fastest =
          std::max(fastest, double(glm::length(glm::vec3(glm::dvec3(x[c], y[c], z[c]) - frame))));
    return fastest;
  });
  return world.maxOverRanks(mine);
}

// The part the whole input gives each rank, found from the cells' layout alone (no values read;
// the same cells give the same partition), and the window of values this rank reads: its part
// grown by the cells it keeps and two finest cells, and the cells whose tents reach them.
struct RankWindow {
  mpi::DataPartition partition;  // finest-cell units of the field
  formats::ValueWindow window;
  bricks::CheckedCells cells;  // the layout, which the second read must give
  flow::VectorVolume layout;   // the cells' bricks and regions, without values
  flow::VolumeBuildTimes layoutTimes;
  std::optional<double> fastest;  // in cell mode
};

RankWindow rankWindow(const MpiWorld& world, const TraceJob& job, std::uint32_t haloSteps) {
  formats::ValueWindow nothing;
  nothing.withChannels = false;
  formats::WindowedRead read;
  const bricks::AmrField layoutCells =
      formats::loadInput(job.dataset.input, job.dataset.builtin, &nothing, &read);
  const FieldPlan plan = planField(flow::ChannelCatalog{layoutCells.source(), read.channels},
                                   layoutCells.info(), job.field);
  RankWindow r;
  r.layout = flow::buildCellLayout(layoutCells, plan.volume, &r.layoutTimes);
  const flow::VectorVolume& layout = r.layout;
  if (job.trace.stepMode == "cell") r.fastest = fastestOverRanks(world, job, layoutCells);
  const RankReach reach =
      rankReach(layout, plan.vector, traceOptions(job.trace, layout), haloSteps, r.fastest);
  r.partition = mpi::partitionCells(layoutCells, world.size(), reach.halo);
  r.window = mpi::partWindow(r.partition, world.rank(), reach.kept + 2.0, layoutCells.bounds(),
                             layout.periodic);
  r.cells.lowers.assign(layoutCells.lowers().begin(), layoutCells.lowers().end());
  r.cells.levels.assign(layoutCells.levels().begin(), layoutCells.levels().end());
  return r;
}

std::string pieceNoun(const std::string& input) {
  switch (formats::detectFormat(input)) {
    case formats::Format::Amrex:
      return "boxes";
    case formats::Format::Enzo:
      return "grids";
    case formats::Format::Flash:
      return "leaf blocks";
    default:
      return "pieces";
  }
}

std::string wholeReadReason(const TraceJob& job) {
  const formats::Format format = formats::detectFormat(job.dataset.input);
  if (!formats::readsValueWindows(format))
    return fmt::format("{} inputs are read whole", formats::formatName(format));
  if (flow::parseGradientRequest(job.field.vector))
    return "a gradient vector at a part's edge takes the cells beyond it";
  if (parseFrameVelocity(job.field.frameVelocity).automatic)
    return "the frame velocity auto is the mean over the whole seeding region";
  if (job.trace.stepMode == "time")
    return "in time mode the default step and a step's reach depend on the fastest vector";
  return "with the linear interpolant in cell mode a step's reach depends on its gradients";
}

RankPart prepareRank(const MpiWorld& world, const TraceJob& job, std::uint32_t haloSteps,
                     const Reporter& reporter) {
  RankPart rank;
  std::optional<InputShare> share;
  std::optional<double> fastest;
  std::optional<mpi::DataPartition> partition;  // found from the layout, in the field's units
  bricks::CheckedCells checkedCells;
  if (readsItsPartAlone(job)) {
    RankWindow window = rankWindow(world, job, haloSteps);
    fastest = window.fastest;
    checkedCells = std::move(window.cells);
    share.emplace();
    share->window = std::move(window.window);
    share->window.checked = &checkedCells;
    share->layout = std::move(window.layout);
    share->layoutTimes = window.layoutTimes;
    share->cells = mpi::shareOverRanks(world);
    partition = window.partition;
    share->markOwned = [&world, partition = std::move(window.partition)](
                           const bricks::AmrField& cells, std::vector<std::uint8_t>& owned) {
      // Every rank has read its window (a rank that failed to is in the agreement of the phase
      // around) before they choose the seeds together.
      mpi::agreed(world, [] {});
      owned = mpi::ownedCells(cells, partition, world.rank());
    };
  }
  rank.prepared.emplace(share ? prepareShare(job, *share, reporter)
                              : prepare(job, {true, KeepDataset::Yes}, reporter));
  PreparedJob::Impl& input = rank.prepared->impl();
  checkedCells = {};
  if (share) rank.read = share->read;
  checkDataVolume(input.volume());
  const bricks::AmrField& cells = input.cells();
  // The vector as the whole volume has it, with the frame velocity auto found there.
  flow::VectorChannels vector = input.field.impl().vector;
  vector.frameVelocity = input.volume().frameVelocity;
  const RankReach reach = rankReach(input.volume(), vector, input.options, haloSteps, fastest);
  rank.halo = reach.halo;
  if (partition) {
    rank.partition = std::move(*partition);
  } else {
    // The whole input is here and so are the seeds: the cuts balance lines as well as cells.
    std::vector<glm::dvec3> seedCells(input.seeds.points.size());
    for (std::size_t i = 0; i < seedCells.size(); ++i)
      seedCells[i] = cells.transform().toCellUnits(input.seeds.points[i]);
    rank.partition = mpi::partitionCells(cells, world.size(), rank.halo, seedCells);
  }
  // The parts in the volume's cell units: buildCellLayout centres cells that lie far from the
  // origin.
  const glm::ivec3 shift = input.volume().domain.lower - cells.bounds().lower;
  for (std::size_t k = 0; k < rank.partition.lower.size(); ++k) {
    rank.partition.lower[k] += shift;
    rank.partition.upper[k] += shift;
  }
  input.options.pauseOutside =
      mpi::pauseBox(rank.partition, world.rank(), reach.margin, input.volume().periodic);
  rank.plan = flow::planLines(input.volume(), input.seeds.points, input.options.direction);
  rank.allBricks = input.volume().bricks.size();

  const glm::ivec3 lower = rank.partition.lower[std::size_t(world.rank())];
  const glm::ivec3 upper = rank.partition.upper[std::size_t(world.rank())];
  flow::VolumeOptions part;  // as the whole volume's (api/field.cpp), cropped
  part.pointData = input.volume().channelNames;
  part.periodic = input.volume().periodic;
  part.interpolant = input.volume().interpolant;
  part.keepAround =
      flow::VolumeOptions::Box{glm::dvec3(lower) - reach.kept, glm::dvec3(upper) + reach.kept};
  // Cropped from the whole volume's bricks, which the cells gave, without building them again.
  flow::VectorVolume cropped = flow::cropCellLayout(input.volume(), part);
  flow::fillVolumeValues(cropped, cells, vector, part);
  input.volume() = std::move(cropped);
  input.releaseDataset();
  return rank;
}

// The "ranks", "read", "device" and "rounds" lines of a trace over data.
struct RankLines {
  const MpiWorld& world;
  const RankPart& rank;
  const TraceJob& job;
  const mpi::RoundStats& stats;
  const std::optional<gpu::GpuTracer>& gpuTracer;
  std::vector<double> bricks, lines, cells, sent, tracing, exchange, read, preparing, device;
  double handOffs = 0.0;

  void say(const Log& log) const {
    amrstream::say(
        log, fmt::format("ranks      {} over data: bricks held {} of {} (cropped to the part and "
                         "a halo of {:.0f} finest cells), cells {}, lines starting {}, rounds "
                         "{}, hand-offs {} ({:.3g} MB), tracing {} s, handing on {} s",
                         world.size(), perRank(bricks, "{:.0f}"), rank.allBricks, rank.halo,
                         perRank(cells, "{:.3g}"), perRank(lines, "{:.0f}"), stats.rounds,
                         perRank(sent, "{:.0f}"), handOffs * sizeof(shared::LineState) * 1e-6,
                         perRank(tracing, "{:.3f}"), perRank(exchange, "{:.3f}")));
    if (rank.read.pieces > 0)
      amrstream::say(log, fmt::format("read       each rank its part's values: {} of {} {}; "
                                      "reading and building {} s",
                                      perRank(read, "{:.0f}"), rank.read.pieces,
                                      pieceNoun(job.dataset.input), perRank(preparing, "{:.2f}")));
    else
      amrstream::say(log, fmt::format("read       every rank the whole input: {}; reading and "
                                      "building {} s",
                                      wholeReadReason(job), perRank(preparing, "{:.2f}")));
    if (!gpuTracer) return;
    amrstream::say(log, fmt::format("device     MiB per rank (volume, structure, rounds): {}",
                                    perRank(device, "{:.1f}")));
    const gpu::TraceRunStats& r = gpuTracer->lastRun();
    amrstream::say(
        log, fmt::format("rounds     rank 0, {} rounds: kernel {:.3f} s, ordering and uploading "
                         "lines {:.3f} s, submitting {:.3f} s, waiting for rounds {:.3f} s and "
                         "copies {:.3f} s, unpacking {:.3f} s, reading states back {:.3f} s",
                         r.rounds, r.kernelSeconds.value_or(0.0), r.linesSeconds, r.submitSeconds,
                         r.roundWaitSeconds, r.copyWaitSeconds, r.unpackSeconds, r.statesSeconds));
  }
};

}  // namespace

void traceOverData(const MpiWorld& world, TraceJob job, const DistributedOutput& output,
                   std::uint32_t haloSteps, const std::function<void()>& checkFiles,
                   const Reporter& reporter) {
  const Log& log = reporter.log;
  if (!world.isRoot()) job.seedsOut.clear();  // rank 0 writes it
  Stopwatch preparing;
  RankPart rank = mpi::agreed(world, [&] {
    checkFiles();
    return prepareRank(world, job, haloSteps, reporter);
  });
  const std::vector<double> rankPreparing = world.gatherToRoot(preparing.seconds());
  PreparedJob::Impl& input = rank.prepared->impl();

  std::vector<shared::LineState> owned;
  for (const shared::LineState& s : rank.plan.states)
    if (rank.partition.ownerOf(mpi::cellPointOf(s)) == world.rank()) owned.push_back(s);
  const double ownedLines = double(owned.size());

  // The backend, its device and its tracer for this rank's part.
  input.backend.deviceSlot = unsigned(world.localRank());
  RankTracer tracer;
  mpi::agreed(world, [&] { startRankTracer(tracer, input, rank.plan.states.size(), log); });

  // Rounds exchange lines and sum the live ones: a failure inside ends every rank (main).
  mpi::RoundStats stats;
  Stopwatch clock;
  flow::TraceSet runs = mpi::traceOverData(world, input.volume(), rank.partition, std::move(owned),
                                           input.options, tracer.advance, &stats);
  const double seconds = clock.seconds();
  mpi::agreed(world, [&] {
    if (tracer.ctx) checkValidation(*tracer.ctx);
  });
  const std::optional<gpu::GpuTracer>& gpuTracer = tracer.gpu;
  const double deviceBytes =
      gpuTracer ? double(gpuTracer->setup().volumeBytes + gpuTracer->setup().structureBytes +
                         gpuTracer->lastRun().roundBytes)
                : 0.0;
  RankLines lines{world, rank, job, stats, gpuTracer, {}, {}, {}, {}, {}, {}, {}, {}, {}, 0.0};
  lines.device = world.gatherToRoot(deviceBytes / 0x1p20);
  input.report.traceSeconds = world.maxOverRanks(seconds);
  input.report.setupSeconds = world.maxOverRanks(input.report.setupSeconds);
  lines.bricks = world.gatherToRoot(double(input.volume().bricks.size()));
  lines.lines = world.gatherToRoot(ownedLines);
  lines.cells = world.gatherToRoot(double(input.volume().values.size()));
  lines.sent = world.gatherToRoot(double(stats.linesSent));
  lines.tracing = world.gatherToRoot(stats.traceSeconds);
  lines.exchange = world.gatherToRoot(stats.exchangeSeconds);
  lines.read = world.gatherToRoot(double(rank.read.piecesRead));
  lines.preparing = rankPreparing;
  lines.handOffs = world.sumOverRanks(double(stats.linesSent));
  writeRankRuns(
      world, std::move(runs), rank.plan.layout, input, output, [&] { lines.say(log); }, log);
}

}  // namespace amrstream
