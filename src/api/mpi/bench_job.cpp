#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <optional>

#include "amrstream/bench.hpp"
#include "amrstream/error.hpp"
#include "api/field_plan.hpp"
#include "api/job_state.hpp"
#include "api/stepping.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_runner.hpp"
#include "flow/seed_strategies.hpp"
#include "flow/seeds.hpp"
#include "formats/load_input.hpp"
#include "mpi/rank_agreement.hpp"
#include "mpi/seed_shares.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

namespace {

std::vector<std::size_t> defaultParticleCounts() {
  std::vector<std::size_t> counts;
  for (std::size_t n = 1 << 10; n <= (1 << 20); n *= 2) counts.push_back(n);
  return counts;
}

// `dens` if present, else the first scalar that is not part of the vector, else none.
std::string defaultSeedChannel(const bricks::AmrField& field, const flow::VectorChannels& vector) {
  if (field.findChannel("dens")) return "dens";
  for (const Channel& c : field.channels())
    if (std::find(vector.channels.begin(), vector.channels.end(), c.name) == vector.channels.end())
      return c.name;
  return {};
}

// The paper's seeding (random points in random cells among the densest) on --seed-density, else
// on `dens` or the first scalar that is not part of the vector; a uniform box without scalars.
flow::SeedList benchSeeds(const BenchRequest& o, const bricks::AmrField& field,
                          const flow::VectorVolume& volume, const flow::VectorChannels& vector,
                          std::size_t count, std::string& description) {
  if (!o.seedsFile.empty()) {
    flow::SeedList seeds = flow::readSeedFile(o.seedsFile);
    if (seeds.points.size() < count)
      throw InputError(o.seedsFile, fmt::format("has {} seeds, fewer than the largest particle "
                                                "count {}",
                                                seeds.points.size(), count));
    description = o.seedsFile;
    return seeds;
  }
  const std::string channel =
      o.seedDensity.empty() ? defaultSeedChannel(field, vector) : o.seedDensity;
  if (channel.empty()) {
    description = fmt::format("uniform random in the domain (seed {}; no scalar channel)", o.seed);
    const glm::dvec3 hi = flow::domainUpper(volume) - 1e-4 * volume.transform.spacing;
    return flow::randomSeedsInBox(flow::domainLower(volume), hi, count, o.seed);
  }
  description = fmt::format("random cells with {} at or above its {:g}th percentile (seed {})",
                            channel, o.seedPercentile, o.seed);
  return flow::seedsInDensestCells(field, {channel, o.seedPercentile, false, count, o.seed});
}

bench::BenchConfig makeConfig(const BenchRequest& o, const flow::VectorVolume& volume) {
  bench::BenchConfig config;
  config.backends = o.backends;
  config.particles = o.particles.empty() ? defaultParticleCounts() : o.particles;
  std::sort(config.particles.begin(), config.particles.end());
  config.particles.erase(std::unique(config.particles.begin(), config.particles.end()),
                         config.particles.end());
  config.cpuMaxParticles = o.cpuMaxParticles;
  config.historyModes = o.mode == "endpoints" ? std::vector<bool>{false}
                        : o.mode == "history" ? std::vector<bool>{true}
                                              : std::vector<bool>{false, true};
  config.historyPointBudget = o.historyPoints;
  config.repeats = o.repeats;
  config.trace.stepMode = parseStepMode(o.stepMode);
  config.trace.stepSize = chooseStepSize(config.trace.stepMode, o.stepSize, volume);
  config.trace.maxSteps = o.steps;
  config.trace.roundSteps = o.roundSteps;
  config.trace.cpuTailLines = o.cpuTailLines;
  config.trace.direction = flow::Direction::Forward;  // the paper's experiment
  config.deviceFilter = o.device;
  if (o.regionHint != "default") config.regionHint = o.regionHint == "on";
  if (o.dualValues != "default") config.dualValues = o.dualValues == "on";
  if (o.spreadThreads >= 0) config.spreadThreads = static_cast<std::uint32_t>(o.spreadThreads);
  config.spatialSeedOrder = o.seedOrder == "spatial";
  config.validation = validationRequested();
  return config;
}

struct PreparedBench {
  bench::BenchReport report;
  flow::VectorVolume volume;
  flow::SeedList seeds;
  flow::VolumeBuildTimes times;
};

PreparedBench prepareBench(const BenchRequest& o, const std::function<void()>& checkFiles) {
  if (o.dataset.input.starts_with("builtin:")) checkBuiltinSize(o.dataset.builtin);
  if (!o.particles.empty())
    checkSeedCount(double(*std::max_element(o.particles.begin(), o.particles.end())), "particles");
  checkFiles();

  PreparedBench prepared;
  bench::BenchReport& report = prepared.report;
  report.command = o.commandLine;
  report.host = bench::hostDescription();
  bench::DatasetStats& data = report.dataset;

  Stopwatch clock;
  const bricks::AmrField field = formats::loadInput(o.dataset.input, o.dataset.builtin);
  data.loadSeconds = clock.seconds();
  const flow::VectorChannels vector = flow::chooseVectorChannels(field, o.vector);
  flow::VolumeOptions volumeOptions;
  volumeOptions.interpolant = parseInterpolant(o.interpolant);
  prepared.volume = flow::buildVectorVolume(field, vector, volumeOptions, &prepared.times);
  const flow::VectorVolume& volume = prepared.volume;
  data.source = field.source();
  data.cells = field.cellCount();
  data.finestLevel = field.finestLevel();
  data.coarsestLevel = field.coarsestLevel();
  data.vector = vector.name;
  data.bricks = volume.bricks.size();
  data.regions = volume.regions.regions.size();
  data.bricksSeconds = prepared.times.bricks;
  data.regionsSeconds = prepared.times.regions;
  data.gatherSeconds = prepared.times.gather;
  report.config = makeConfig(o, volume);
  const std::size_t maxParticles = report.config.particles.back();

  prepared.seeds = benchSeeds(o, field, volume, vector, maxParticles, data.seeding);
  flow::checkSeedsInDomain(volume, prepared.seeds);
  return prepared;
}

// Under mpirun every rank runs every row on its share of the particles (mpi::mortonShares);
// rank 0 prints and writes the JSON.
bench::RankShare rankShare(const MpiWorld& world) {
  bench::RankShare share;
  share.indicesOf = [&world](std::span<const glm::dvec3> seeds) {
    return mpi::mortonShares(seeds, world.size())[std::size_t(world.rank())];
  };
  share.synchronize = [&world] { world.barrier(); };
  share.maxOf = [&world](double v) { return world.maxOverRanks(v); };
  share.sumOf = [&world](double v) { return world.sumOverRanks(v); };
  return share;
}

// Without the trailing newline the bench report's table lines end with.
std::string line(std::string text) {
  if (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

void sayPlan(const MpiWorld& world, const BenchRequest& o, const PreparedBench& prepared,
             const Log& log) {
  const bench::BenchReport& report = prepared.report;
  const bench::DatasetStats& data = report.dataset;
  say(log, fmt::format("input      {}: {} cells, levels {}..{}, vector {} [{:.2f} s]", data.source,
                       withCommas(data.cells), data.finestLevel, data.coarsestLevel, data.vector,
                       data.loadSeconds));
  say(log,
      fmt::format(
          "structure  {} bricks [{:.2f} s], {} regions [{:.2f} s], gather [{:.2f} s]{}",
          withCommas(data.bricks), data.bricksSeconds, withCommas(data.regions),
          data.regionsSeconds, data.gatherSeconds,
          prepared.volume.interpolant == flow::Interpolant::Linear
              ? fmt::format(", linear interpolant's gradients [{:.2f} s]", prepared.times.gradients)
              : std::string()));
  say(log, fmt::format("seeds      {} from {}; GPU threads take them in {} order",
                       withCommas(prepared.seeds.points.size()), data.seeding,
                       report.config.spatialSeedOrder ? "Morton (spatial)" : "the given"));
  say(log, fmt::format("stepping   mode {}, h = {:g}, at most {} steps, {} interpolant; best of {}",
                       o.stepMode, report.config.trace.stepSize, o.steps, o.interpolant,
                       report.config.repeats));
  say(log, "host       " + report.host);
  if (world.size() > 1)
    say(log, fmt::format("ranks      {}: each row's particles in blocks of the Morton order dealt "
                         "round the ranks; steps summed, times the slowest rank's, device memory "
                         "the largest rank's",
                         world.size()));
  if (const std::string warning = world.bindingWarning(); !warning.empty())
    say(log, "note       " + warning);
  say(log, "");
}

}  // namespace

void runBench(const MpiWorld& world, const BenchRequest& o, const std::function<void()>& checkFiles,
              const Reporter& reporter) {
  const Log& log = reporter.log;
  PreparedBench prepared = mpi::agreed(world, [&] { return prepareBench(o, checkFiles); });
  bench::BenchReport& report = prepared.report;
  report.ranks = world.size();
  report.config.deviceSlot = unsigned(world.localRank());
  sayPlan(world, o, prepared, log);

  bench::BenchCallbacks callbacks;
  if (world.size() > 1) callbacks.share = rankShare(world);
  bool headerPrinted = false;
  callbacks.setupDone = [&](const bench::BackendSetup& s) {
    say(log, "setup      " + line(bench::setupLine(s)));
  };
  callbacks.rowDone = [&](const bench::BenchRow& row) {
    if (!headerPrinted) say(log, line(bench::tableHeader()));
    headerPrinted = true;
    say(log, line(bench::tableRow(row)));
    // The runner has appended the row: rewriting the JSON now keeps what an interrupted run
    // measured.
    if (world.isRoot()) bench::writeJson(o.json, report);
  };
  callbacks.note = [&](const std::string& note) { say(log, "note       " + note); };
  // Rows synchronise the ranks: a failure here ends them all (main), not by agreement.
  bench::runBenchmark(prepared.volume, prepared.seeds.points, report.config, report, callbacks);

  mpi::agreed(world, [&] {
    if (!world.isRoot()) return;
    bench::writeJson(o.json, report);
    say(log, "");
    say(log, fmt::format("json       {} ({} rows)", o.json, report.rows.size()));
  });
}

}  // namespace amrstream
