#include "distributed_trace.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "dist/gathered_traces.hpp"
#include "dist/rank_agreement.hpp"
#include "dist/seed_ranges.hpp"
#include "dist/trace_exchange.hpp"
#include "option_checks.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

flow::SeedList subset(const flow::SeedList& seeds, const std::vector<std::uint32_t>& indices) {
  flow::SeedList part;
  for (const std::uint32_t i : indices) {
    part.points.push_back(seeds.points[i]);
    if (i < seeds.origins.size()) part.origins.push_back(seeds.origins[i]);
  }
  return part;
}

std::string perRank(const std::vector<double>& values, const char* format) {
  std::string text;
  for (const double v : values)
    text += (text.empty() ? "" : " / ") + fmt::format(fmt::runtime(format), v);
  return text;
}

}  // namespace

void traceDistributed(const dist::MpiWorld& world, TraceJobOptions job, bool keepHistory,
                      const std::function<void()>& checkFiles, const TracesWriter& write) {
  if (!world.isRoot()) job.seedsOut.clear();  // rank 0 writes it
  job.backend.deviceSlot = unsigned(world.localRank());
  PreparedInput input = dist::agreed(world, [&] {
    checkFiles();
    PreparedInput prepared = prepareInput(job);
    prepared.releaseField();
    prepared.options.keepHistory = keepHistory;
    return prepared;
  });

  if (const std::string warning = world.bindingWarning(); !warning.empty())
    fmt::print("note       {}\n", warning);
  const std::vector<std::vector<std::uint32_t>> ranges =
      dist::mortonRanges(input.seeds.points, world.size());
  const std::vector<std::uint32_t>& mine = ranges[std::size_t(world.rank())];
  const std::size_t seedCount = input.seeds.points.size();
  flow::SeedList allSeeds = std::exchange(input.seeds, subset(input.seeds, mine));

  flow::TraceSet part = dist::agreed(world, [&] {
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
  const double bytes = world.sumOverRanks(world.isRoot() ? 0.0 : double(dist::partBytes(part)));

  Stopwatch clock;
  std::vector<flow::TraceSet> parts =
      dist::agreed(world, [&] { return dist::gatherTraces(world, std::move(part)); });
  const double gatherSeconds = clock.seconds();
  dist::agreed(world, [&] {
    if (!world.isRoot()) return;
    const dist::GatheredTraces traces(std::move(parts));
    const auto [fewest, most] = std::ranges::minmax(
        ranges, {}, [](const std::vector<std::uint32_t>& r) { return r.size(); });
    fmt::print("ranks      {} ({} seeds in Morton ranges of {}..{}): steps {}, tracing {} s\n",
               world.size(), seedCount, fewest.size(), most.size(),
               perRank(rankSteps, "{:.3g}"), perRank(rankSeconds, "{:.3f}"));
    fmt::print("gathered   {:.3g} GB to rank 0 in {:.2f} s\n", bytes * 1e-9, gatherSeconds);
    printTraceSummary(traces.lines(), input.report);
    write(traces, input);
  });
}

void addDistributeOption(CLI::App& command, std::string& distribute) {
  command
      .add_option("--distribute", distribute,
                  "under mpirun: seeds (every rank reads the data and traces a Morton range of "
                  "the seeds; rank 0 writes the result) or data (not available yet)")
      ->capture_default_str()
      ->check(CLI::IsMember({"seeds", "data"}));
}

void checkDistributeOption(const std::string& distribute) {
  if (distribute == "data")
    throw InputError("--distribute",
                     "data (bricks partitioned in space among the ranks) is not available yet; "
                     "use --distribute seeds");
}

}  // namespace amrstream::cli
