#include "api/mpi/seed_distributed_trace.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "amrstream/distributed.hpp"
#include "api/device.hpp"
#include "api/held_traces.hpp"
#include "api/mpi/rank_rounds.hpp"
#include "mpi/even_lines.hpp"
#include "mpi/gathered_traces.hpp"
#include "mpi/rank_agreement.hpp"
#include "mpi/seed_shares.hpp"
#include "mpi/trace_exchange.hpp"
#include "output/pvtp_writer.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

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

std::string writtenLine(const std::filesystem::path& path, double lines, double points,
                        double seconds, const std::string& pieces) {
  return fmt::format("output     {} ({}{} polylines, {} points) [{:.2f} s]", path.string(), pieces,
                     withCommas(std::uint64_t(lines)), withCommas(std::uint64_t(points)), seconds);
}

}  // namespace

std::string perRank(const std::vector<double>& values, const char* format) {
  std::string text;
  for (const double v : values)
    text += (text.empty() ? "" : " / ") + fmt::format(fmt::runtime(format), v);
  return text;
}

void writePieces(const MpiWorld& world, flow::TraceSet part, PreparedJob::Impl& input,
                 const DistributedOutput& output, const std::function<void()>& saySummary,
                 const Log& log) {
  const std::filesystem::path pvtp = output.output.path;
  const std::filesystem::path piece = piecePath(pvtp, world.rank());
  flow::TraceSet lines = mpi::withoutPoints(part);
  try {
    Stopwatch clock;
    std::vector<flow::TraceSet> own;
    own.push_back(std::move(part));
    TraceOutput pieceOutput = output.output;
    pieceOutput.path = piece.string();
    const WrittenLines counts = mpi::agreed(world, [&] {
      return writeLines(mpi::GatheredTraces(std::move(own)), pieceOutput, jobProvenance(input));
    });
    const double seconds = world.maxOverRanks(clock.seconds());
    const double written = world.sumOverRanks(double(counts.lines));
    const double points = world.sumOverRanks(double(counts.points));
    std::vector<flow::TraceSet> parts =
        mpi::agreed(world, [&] { return mpi::gatherTraces(world, std::move(lines)); });
    mpi::agreed(world, [&] {
      if (!world.isRoot()) return;
      const mpi::GatheredTraces traces(std::move(parts));
      saySummary();
      sayTraceSummary(traces.lines(), input.report, log);
      std::vector<std::filesystem::path> pieces;
      for (int rank = 0; rank < world.size(); ++rank) pieces.push_back(piecePath(pvtp, rank));
      output::writePvtp(pvtp, pieces);
      say(log, writtenLine(pvtp, written, points, seconds,
                           fmt::format("{} pieces {}, ", world.size(),
                                       piecePath(pvtp, 0).filename().string() + "..")));
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
void traceInRebalancedRounds(const MpiWorld& world, PreparedJob::Impl& input,
                             const std::vector<std::vector<std::uint32_t>>& shares,
                             std::uint32_t steps, const DistributedOutput& output, const Log& log) {
  input.options.roundSteps = steps;
  const flow::LinePlan plan =
      flow::planLines(input.volume(), input.seeds.points, input.options.direction);
  std::vector<std::uint8_t> mine(input.seeds.points.size(), 0);
  for (const std::uint32_t seed : shares[std::size_t(world.rank())]) mine[seed] = 1;
  std::vector<shared::LineState> owned;
  for (const shared::LineState& s : plan.states)
    if (mine[plan.layout.seedIds[s.line]] != 0) owned.push_back(s);

  RankTracer tracer;
  mpi::agreed(world, [&] { startRankTracer(tracer, input, owned.size(), log); });
  mpi::RoundStats stats;
  Stopwatch clock;
  flow::TraceSet runs = mpi::traceInRounds(world, input.volume(), std::move(owned), input.options,
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
  const auto sayRanks = [&] {
    say(log, fmt::format("ranks      {} over seeds, the live lines evened out every {} steps: "
                         "rounds {}, lines handed on {}, tracing {} s, handing on {} s",
                         world.size(), steps, stats.rounds, perRank(rankSent, "{:.0f}"),
                         perRank(rankTracing, "{:.3f}"), perRank(rankExchange, "{:.3f}")));
  };
  writeRankRuns(world, std::move(runs), plan.layout, input, output, sayRanks, log);
}

// Rank 0 gathers every rank's lines and writes them as one process would.
void gatherAndWrite(const MpiWorld& world, flow::TraceSet part, PreparedJob::Impl& input,
                    const DistributedOutput& output, const std::function<void()>& sayRanks,
                    const Log& log) {
  const double bytes = world.sumOverRanks(world.isRoot() ? 0.0 : double(mpi::partBytes(part)));
  Stopwatch clock;
  std::vector<flow::TraceSet> parts =
      mpi::agreed(world, [&] { return mpi::gatherTraces(world, std::move(part)); });
  const double gatherSeconds = clock.seconds();
  mpi::agreed(world, [&] {
    if (!world.isRoot()) return;
    const mpi::GatheredTraces traces(std::move(parts));
    sayRanks();
    say(log,
        fmt::format("gathered   {:.3g} GB to rank 0 in {:.2f} s", bytes * 1e-9, gatherSeconds));
    sayTraceSummary(traces.lines(), input.report, log);
    const WrittenLines written = writeLines(traces, output.output, jobProvenance(input));
    say(log, outputLine(output.output.path, written));
  });
}

}  // namespace

void traceOverSeeds(const MpiWorld& world, TraceJob job, const DistributedOutput& output,
                    std::uint32_t rebalanceSteps, const std::function<void()>& checkFiles,
                    const Reporter& reporter) {
  const Log& log = reporter.log;
  if (!world.isRoot()) job.seedsOut.clear();  // rank 0 writes it
  job.backend.deviceSlot = unsigned(world.localRank());
  PreparedJob prepared = mpi::agreed(world, [&] {
    checkFiles();
    return prepare(job, {true, KeepDataset::No}, reporter);
  });
  PreparedJob::Impl& input = prepared.impl();

  if (const std::string warning = world.bindingWarning(); !warning.empty())
    say(log, "note       " + warning);
  const std::vector<std::vector<std::uint32_t>> shares =
      mpi::mortonShares(input.seeds.points, world.size());
  if (rebalanceSteps > 0)
    return traceInRebalancedRounds(world, input, shares, rebalanceSteps, output, log);
  const std::vector<std::uint32_t>& mine = shares[std::size_t(world.rank())];
  const std::size_t seedCount = input.seeds.points.size();
  flow::SeedList allSeeds = std::exchange(input.seeds, subset(input.seeds, mine));

  flow::TraceSet part = mpi::agreed(world, [&] {
    const std::size_t seeds = input.seeds.points.size();
    flow::TraceSet traced =
        traceSeeds(
            input.backend, input.volume(), input.seeds.points, input.options,
            [&](std::size_t done, std::size_t lines) {
              reporter.advance("tracing", done * seeds / std::max<std::size_t>(1, lines), seeds);
            },
            &input.report, HostValues::Release, log)
            .assemble();
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
  const auto sayRanks = [&] {
    const auto [fewest, most] = std::ranges::minmax(
        shares, {}, [](const std::vector<std::uint32_t>& r) { return r.size(); });
    say(log, fmt::format("ranks      {} ({} seeds, {}..{} a rank in blocks of the Morton order): "
                         "steps {}, tracing {} s",
                         world.size(), seedCount, fewest.size(), most.size(),
                         perRank(rankSteps, "{:.3g}"), perRank(rankSeconds, "{:.3f}")));
  };
  if (output.pieces) return writePieces(world, std::move(part), input, output, sayRanks, log);
  gatherAndWrite(world, std::move(part), input, output, sayRanks, log);
}

}  // namespace amrstream
