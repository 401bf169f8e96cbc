#include "distributed_trace.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "amrstream/backend.hpp"
#include "mpi/even_lines.hpp"
#include "mpi/gathered_traces.hpp"
#include "mpi/rank_agreement.hpp"
#include "mpi/seed_shares.hpp"
#include "mpi/trace_exchange.hpp"
#include "option_checks.hpp"
#include "output/pvtp_writer.hpp"
#include "rank_rounds.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

flow::SeedList subset(const flow::SeedList& seeds, const std::vector<std::uint32_t>& indices) {
  flow::SeedList part;
  part.points.reserve(indices.size());
  for (const std::uint32_t i : indices) part.points.push_back(seeds.points[i]);
  part.origin = [all = flow::SeedList{{}, seeds.origin}, indices](std::size_t i) {
    return all.originOf(indices[i]);
  };
  return part;
}

}  // namespace

std::string perRank(const std::vector<double>& values, const char* format) {
  std::string text;
  for (const double v : values)
    text += (text.empty() ? "" : " / ") + fmt::format(fmt::runtime(format), v);
  return text;
}

std::filesystem::path piecePath(const std::filesystem::path& pvtp, int rank) {
  return pvtp.parent_path() / fmt::format("{}_{}.vtp", pvtp.stem().string(), rank);
}

namespace {

void printWritten(const std::filesystem::path& path, double lines, double points, double seconds,
                  const std::string& pieces = "") {
  fmt::print("output     {} ({}{} polylines, {} points) [{:.2f} s]\n", path.string(), pieces,
             withCommas(std::uint64_t(lines)), withCommas(std::uint64_t(points)), seconds);
}

}  // namespace

void writePieces(const mpi::MpiWorld& world, flow::TraceSet part, PreparedInput& input,
                 const DistributedOutput& output, const std::function<void()>& printSummary) {
  const std::filesystem::path piece = piecePath(output.path, world.rank());
  flow::TraceSet lines = mpi::withoutPoints(part);
  try {
    Stopwatch clock;
    std::vector<flow::TraceSet> own;
    own.push_back(std::move(part));
    const output::VtpCounts counts = mpi::agreed(
        world, [&] { return output.write(piece, mpi::GatheredTraces(std::move(own)), input); });
    const double seconds = world.maxOverRanks(clock.seconds());
    const double written = world.sumOverRanks(double(counts.lines));
    const double points = world.sumOverRanks(double(counts.points));
    std::vector<flow::TraceSet> parts =
        mpi::agreed(world, [&] { return mpi::gatherTraces(world, std::move(lines)); });
    mpi::agreed(world, [&] {
      if (!world.isRoot()) return;
      const mpi::GatheredTraces traces(std::move(parts));
      printSummary();
      printTraceSummary(traces.lines(), input.report);
      std::vector<std::filesystem::path> pieces;
      for (int rank = 0; rank < world.size(); ++rank)
        pieces.push_back(piecePath(output.path, rank));
      output::writePvtp(output.path, pieces);
      printWritten(output.path, written, points, seconds,
                   fmt::format("{} pieces {}, ", world.size(),
                               piecePath(output.path, 0).filename().string() + ".."));
    });
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(piece, ignored);
    throw;
  }
}

namespace {

// Over seeds in rounds of `steps` steps, the live lines evened out among the ranks between them
// (mpi/even_lines.hpp): the ranks' runs of each line are put together as over data.
void traceInRebalancedRounds(const mpi::MpiWorld& world, TraceJobOptions& job, PreparedInput& input,
                             const std::vector<std::vector<std::uint32_t>>& shares,
                             std::uint32_t steps, const DistributedOutput& output) {
  input.options.roundSteps = steps;
  const flow::LinePlan plan =
      flow::planLines(input.volume, input.seeds.points, input.options.direction);
  std::vector<std::uint8_t> mine(input.seeds.points.size(), 0);
  for (const std::uint32_t seed : shares[std::size_t(world.rank())]) mine[seed] = 1;
  std::vector<shared::LineState> owned;
  for (const shared::LineState& s : plan.states)
    if (mine[plan.layout.seedIds[s.line]] != 0) owned.push_back(s);

  RankTracer tracer;
  mpi::agreed(world, [&] { startRankTracer(tracer, job, input, owned.size()); });
  mpi::RoundStats stats;
  Stopwatch clock;
  flow::TraceSet runs = mpi::traceInRounds(world, input.volume, std::move(owned), input.options,
                                           tracer.advance, mpi::evenOutLines(world), &stats);
  const double seconds = clock.seconds();
  mpi::agreed(world, [&] {
    if (tracer.ctx) checkValidation(*tracer.ctx);
  });
  input.report.traceSeconds = world.maxOverRanks(seconds);
  input.report.setupSeconds = world.maxOverRanks(input.report.setupSeconds);
  const std::vector<double> rankSent = world.gatherToRoot(double(stats.linesSent));
  const std::vector<double> rankTracing = world.gatherToRoot(stats.traceSeconds);
  const std::vector<double> rankExchange = world.gatherToRoot(stats.exchangeSeconds);
  const auto printRanks = [&] {
    fmt::print(
        "ranks      {} over seeds, the live lines evened out every {} steps: rounds {}, "
        "lines handed on {}, tracing {} s, handing on {} s\n",
        world.size(), steps, stats.rounds, perRank(rankSent, "{:.0f}"),
        perRank(rankTracing, "{:.3f}"), perRank(rankExchange, "{:.3f}"));
  };
  writeRankRuns(world, std::move(runs), plan.layout, input, output, printRanks);
}

}  // namespace

void traceDistributed(const mpi::MpiWorld& world, TraceJobOptions job, bool keepHistory,
                      std::uint32_t rebalanceSteps, const std::function<void()>& checkFiles,
                      const DistributedOutput& output) {
  if (!world.isRoot()) job.seedsOut.clear();  // rank 0 writes it
  job.backend.deviceSlot = unsigned(world.localRank());
  PreparedInput input = mpi::agreed(world, [&] {
    checkFiles();
    PreparedInput prepared = prepareInput(job, true, CellsAfter::Release);
    prepared.releaseField();
    prepared.options.keepHistory = keepHistory;
    return prepared;
  });

  if (const std::string warning = world.bindingWarning(); !warning.empty())
    fmt::print("note       {}\n", warning);
  const std::vector<std::vector<std::uint32_t>> shares =
      mpi::mortonShares(input.seeds.points, world.size());
  if (rebalanceSteps > 0)
    return traceInRebalancedRounds(world, job, input, shares, rebalanceSteps, output);
  const std::vector<std::uint32_t>& mine = shares[std::size_t(world.rank())];
  const std::size_t seedCount = input.seeds.points.size();
  flow::SeedList allSeeds = std::exchange(input.seeds, subset(input.seeds, mine));

  flow::TraceSet part = mpi::agreed(world, [&] {
    flow::TraceSet traced = std::move(traceSeeds(job, input, HostValues::Release)).assemble();
    for (std::uint32_t& id : traced.seedIds) id = mine[id];
    return traced;
  });
  input.seeds = std::move(allSeeds);  // the output's provenance names them all
  double steps = 0.0;
  for (const std::uint32_t s : part.steps) steps += s;
  const std::vector<double> rankSteps = world.gatherToRoot(steps);
  const std::vector<double> rankSeconds = world.gatherToRoot(input.report.traceSeconds);
  input.report.traceSeconds = world.maxOverRanks(input.report.traceSeconds);
  input.report.setupSeconds = world.maxOverRanks(input.report.setupSeconds);
  const auto printRanks = [&] {
    const auto [fewest, most] = std::ranges::minmax(
        shares, {}, [](const std::vector<std::uint32_t>& r) { return r.size(); });
    fmt::print(
        "ranks      {} ({} seeds, {}..{} a rank in blocks of the Morton order): steps {}, "
        "tracing {} s\n",
        world.size(), seedCount, fewest.size(), most.size(), perRank(rankSteps, "{:.3g}"),
        perRank(rankSeconds, "{:.3f}"));
  };
  if (output.pieces) return writePieces(world, std::move(part), input, output, printRanks);

  const double bytes = world.sumOverRanks(world.isRoot() ? 0.0 : double(mpi::partBytes(part)));
  Stopwatch clock;
  std::vector<flow::TraceSet> parts =
      mpi::agreed(world, [&] { return mpi::gatherTraces(world, std::move(part)); });
  const double gatherSeconds = clock.seconds();
  mpi::agreed(world, [&] {
    if (!world.isRoot()) return;
    const mpi::GatheredTraces traces(std::move(parts));
    printRanks();
    fmt::print("gathered   {:.3g} GB to rank 0 in {:.2f} s\n", bytes * 1e-9, gatherSeconds);
    printTraceSummary(traces.lines(), input.report);
    clock.restart();
    const output::VtpCounts counts = output.write(output.path, traces, input);
    printWritten(output.path, double(counts.lines), double(counts.points), clock.seconds());
  });
}

void addDistributeOption(CLI::App& command, std::string& distribute) {
  command
      .add_option("--distribute", distribute,
                  "under mpirun: seeds (every rank holds the data and traces its share of the "
                  "seeds) or data (every rank holds its part of space and traces the lines "
                  "there, handing them on as they leave)")
      ->capture_default_str()
      ->check(CLI::IsMember({"seeds", "data"}));
}

}  // namespace amrstream::cli
