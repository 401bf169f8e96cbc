#include "bench_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <optional>

#include "amrstream/backend.hpp"
#include "amrstream/field.hpp"
#include "amrstream/seeding.hpp"
#include "amrstream/trace_settings.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_runner.hpp"
#include "dataset_files.hpp"
#include "dataset_options.hpp"
#include "flow/seed_strategies.hpp"
#include "flow/seeds.hpp"
#include "formats/load_input.hpp"
#include "mpi/mpi_world.hpp"
#include "mpi/rank_agreement.hpp"
#include "mpi/seed_shares.hpp"
#include "option_checks.hpp"
#include "option_limits.hpp"
#include "output_paths.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct BenchCommandOptions {
  DatasetOptions dataset;
  std::string vector;
  std::vector<std::string> backends{"cpu", "rayquery", "pipeline", "compute"};
  std::vector<std::size_t> particles;
  std::size_t cpuMaxParticles = 65536;
  std::string mode = "both";
  std::uint64_t historyPoints = std::uint64_t(1) << 28;
  std::uint32_t repeats = 1;
  std::uint32_t steps = 1000;
  std::uint32_t roundSteps = 0;
  std::uint32_t cpuTailLines = 0;
  std::optional<float> stepSize;
  std::string stepMode = "cell";
  std::string interpolant = "tent";
  std::string seedsFile;
  std::string seedDensity;
  double seedPercentile = 90.0;
  std::uint64_t seed = 1;
  std::string device;
  std::string regionHint = "default";
  std::string dualValues = "default";
  std::int64_t spreadThreads = -1;
  std::string seedOrder = "spatial";
  std::string json = "bench.json";
  std::string commandLine;
};

std::vector<std::size_t> defaultParticleCounts() {
  std::vector<std::size_t> counts;
  for (std::size_t n = 1 << 10; n <= (1 << 20); n *= 2) counts.push_back(n);
  return counts;
}

// `dens` if present, else the first scalar that is not part of the vector, else none.
std::string defaultSeedChannel(const bricks::AmrField& field, const flow::VectorChannels& vector) {
  if (field.findChannel("dens")) return "dens";
  for (const bricks::Channel& c : field.channels())
    if (std::find(vector.channels.begin(), vector.channels.end(), c.name) == vector.channels.end())
      return c.name;
  return {};
}

// The paper's seeding (random points in random cells among the densest) on --seed-density, else
// on `dens` or the first scalar that is not part of the vector; a uniform box without scalars.
flow::SeedList benchSeeds(const BenchCommandOptions& o, const bricks::AmrField& field,
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

bench::BenchConfig makeConfig(const BenchCommandOptions& o, const flow::VectorVolume& volume) {
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

PreparedBench prepareBench(const BenchCommandOptions& o) {
  checkBuiltinSize(o.dataset);
  if (!o.particles.empty())
    checkSeedCount(double(*std::max_element(o.particles.begin(), o.particles.end())),
                   "--particles");
  RunFiles files;
  files.addInputs(datasetFiles(o.dataset.input));
  if (!o.seedsFile.empty()) files.addInput(o.seedsFile);
  files.addOutput("--json", o.json);

  PreparedBench prepared;
  bench::BenchReport& report = prepared.report;
  report.command = o.commandLine;
  report.host = bench::hostDescription();
  bench::DatasetStats& data = report.dataset;

  Stopwatch clock;
  const bricks::AmrField field = formats::loadInput(o.dataset.input, o.dataset.generator);
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
bench::RankShare rankShare(const mpi::MpiWorld& world) {
  bench::RankShare share;
  share.ranks = world.size();
  share.indicesOf = [&world](std::span<const glm::dvec3> seeds) {
    return mpi::mortonShares(seeds, world.size())[std::size_t(world.rank())];
  };
  share.synchronize = [&world] { world.barrier(); };
  share.maxOf = [&world](double v) { return world.maxOverRanks(v); };
  share.sumOf = [&world](double v) { return world.sumOverRanks(v); };
  return share;
}

void runBench(const BenchCommandOptions& o, const mpi::MpiWorld& world) {
  PreparedBench prepared = mpi::agreed(world, [&] { return prepareBench(o); });
  bench::BenchReport& report = prepared.report;
  const bench::DatasetStats& data = report.dataset;
  const flow::VectorVolume& volume = prepared.volume;
  const flow::SeedList& seeds = prepared.seeds;
  report.ranks = world.size();
  report.config.deviceSlot = unsigned(world.localRank());

  fmt::print("input      {}: {} cells, levels {}..{}, vector {} [{:.2f} s]\n", data.source,
             withCommas(data.cells), data.finestLevel, data.coarsestLevel, data.vector,
             data.loadSeconds);
  fmt::print(
      "structure  {} bricks [{:.2f} s], {} regions [{:.2f} s], gather [{:.2f} s]{}\n",
      withCommas(data.bricks), data.bricksSeconds, withCommas(data.regions), data.regionsSeconds,
      data.gatherSeconds,
      volume.interpolant == flow::Interpolant::Linear
          ? fmt::format(", linear interpolant's gradients [{:.2f} s]", prepared.times.gradients)
          : std::string());
  fmt::print("seeds      {} from {}; GPU threads take them in {} order\n",
             withCommas(seeds.points.size()), data.seeding,
             report.config.spatialSeedOrder ? "Morton (spatial)" : "the given");
  fmt::print("stepping   mode {}, h = {:g}, at most {} steps, {} interpolant; best of {}\n",
             o.stepMode, report.config.trace.stepSize, o.steps, o.interpolant,
             report.config.repeats);
  fmt::print("host       {}\n", report.host);
  if (world.size() > 1)
    fmt::print(
        "ranks      {}: each row's particles in blocks of the Morton order dealt round the "
        "ranks; steps "
        "summed, times the slowest rank's, device memory the largest rank's\n",
        world.size());
  if (const std::string warning = world.bindingWarning(); !warning.empty())
    fmt::print("note       {}\n", warning);
  fmt::print("\n");

  bench::BenchCallbacks callbacks;
  if (world.size() > 1) callbacks.share = rankShare(world);
  bool headerPrinted = false;
  callbacks.setupDone = [](const bench::BackendSetup& s) {
    fmt::print("setup      {}", bench::setupLine(s));
  };
  callbacks.rowDone = [&](const bench::BenchRow& row) {
    if (!headerPrinted) fmt::print("{}", bench::tableHeader());
    headerPrinted = true;
    fmt::print("{}", bench::tableRow(row));
    std::fflush(stdout);
    // The runner has appended the row: rewriting the JSON now keeps what an interrupted run
    // measured.
    if (world.isRoot()) bench::writeJson(o.json, report);
  };
  callbacks.note = [](const std::string& note) { fmt::print("note       {}\n", note); };
  // Rows synchronise the ranks: a failure here ends them all (main), not by agreement.
  bench::runBenchmark(volume, seeds.points, report.config, report, callbacks);

  mpi::agreed(world, [&] {
    if (!world.isRoot()) return;
    bench::writeJson(o.json, report);
    fmt::print("\njson       {} ({} rows)\n", o.json, report.rows.size());
  });
}

}  // namespace

void addBenchCommand(CLI::App& app, const std::string& commandLine, const mpi::MpiWorld& world) {
  auto options = std::make_shared<BenchCommandOptions>();
  options->commandLine = commandLine;
  CLI::App* command = app.add_subcommand(
      "bench", "the paper's performance experiment: particle-steps per second of every backend");
  addDatasetOptions(*command, options->dataset, "--gen-seed");
  command->add_option("--vector", options->vector, "three channels forming the vector");
  command
      ->add_option("--backends", options->backends,
                   "backends in run order; those the device lacks are noted and skipped")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"rayquery", "pipeline", "compute", "cpu"}));
  command
      ->add_option("--particles", options->particles,
                   "particle counts, comma-separated [default: 1024,2048,...,1048576]")
      ->delimiter(',')
      ->check(countIn(1, kMaxSeedCount));
  command
      ->add_option("--cpu-max-particles", options->cpuMaxParticles,
                   "the CPU path runs counts up to this")
      ->capture_default_str()
      ->check(countIn(0, kMaxSeedCount));
  command
      ->add_option("--mode", options->mode,
                   "endpoints (keep only the last point), history (every step), or both")
      ->capture_default_str()
      ->check(CLI::IsMember({"endpoints", "history", "both"}));
  command
      ->add_option("--history-points", options->historyPoints,
                   "history rows storing more trace points than this are skipped")
      ->capture_default_str()
      ->check(countIn(1, kMaxHistoryPoints));
  command->add_option("--repeats", options->repeats, "runs per row; the fastest is kept")
      ->capture_default_str()
      ->check(countIn(1, kMaxRepeats));
  command->add_option("--steps", options->steps, "maximum integration steps per particle")
      ->capture_default_str()
      ->check(countIn(1, kMaxSteps));
  command
      ->add_option("--round-steps", options->roundSteps,
                   "steps per round on the GPU, the lines that ended dropped between rounds "
                   "(0: every step in one round without history, as many as the rounds' "
                   "memory holds with it)")
      ->capture_default_str()
      ->check(countIn(0, kMaxSteps));
  command
      ->add_option("--cpu-tail", options->cpuTailLines,
                   "GPU rows: once a round leaves this many running lines or fewer, the CPU "
                   "finishes them on all cores (0: never; without history the GPU then runs "
                   "rounds of an eighth of the steps, at least 1000)")
      ->capture_default_str()
      ->check(countIn(0, kMaxLineCount));
  command
      ->add_option("--step-size", options->stepSize,
                   "h: in cell widths (cell, arc) or physical time (time) [default 0.25]")
      ->check(positiveFloat());
  command->add_option("--interpolant", options->interpolant, "tent (paper) or linear")
      ->capture_default_str()
      ->check(CLI::IsMember({"tent", "linear"}));
  command->add_option("--step-mode", options->stepMode, "cell (paper), time or arc")
      ->capture_default_str()
      ->check(CLI::IsMember({"cell", "time", "arc"}));
  auto* seedsFile = command
                        ->add_option("--seeds", options->seedsFile,
                                     "seed points, one 'x y z' per line (at least the largest "
                                     "particle count)")
                        ->check(regularFile());
  command
      ->add_option("--seed-density", options->seedDensity,
                   "the scalar whose densest cells get the seeds [default: dens, else the first "
                   "scalar outside the vector]")
      ->excludes(seedsFile);
  command
      ->add_option("--seed-percentile", options->seedPercentile,
                   "candidate cells are at or above this percentile of the scalar")
      ->capture_default_str()
      ->check(numberIn(0.0, 100.0))
      ->excludes(seedsFile);
  command->add_option("--seed", options->seed, "random seed for the seed points")
      ->capture_default_str()
      ->check(countIn(0, std::numeric_limits<std::uint64_t>::max()))
      ->excludes(seedsFile);
  command->add_option("--device", options->device,
                      "the Vulkan device whose name contains this (see `amrstream devices`)");
  command
      ->add_option("--region-hint", options->regionHint,
                   "GPU samples test the previous sample's region before locating: on, off "
                   "(every sample runs the point location) or each backend's default (on)")
      ->capture_default_str()
      ->check(CLI::IsMember({"default", "on", "off"}));
  command
      ->add_option("--dual-values", options->dualValues,
                   "GPU kernels read the vector as dual cells, the 8 values of each 2x2x2 block "
                   "of a brick together (8 times the values' memory; tent interpolant): on, off "
                   "or the default")
      ->capture_default_str()
      ->check(CLI::IsMember({"default", "on", "off"}));
  command
      ->add_option("--spread-threads", options->spreadThreads,
                   "GPU rounds of fewer lines than this give each line up to 32 invocations, "
                   "the first tracing it, at most this many in all (0: one invocation a line; "
                   "-1: the default, 131072 for compute and rayquery on GPUs, 65536 for pipeline, "
                   "0 on CPU devices)")
      ->capture_default_str()
      ->check(CLI::Range(std::int64_t(-1), std::int64_t(kMaxLineCount)));
  command
      ->add_option("--seed-order", options->seedOrder,
                   "spatial: GPU threads take seeds in Morton order of their positions; given: "
                   "in the order drawn")
      ->capture_default_str()
      ->check(CLI::IsMember({"spatial", "given"}));
  command->add_option("--json", options->json, "where to write the results")->capture_default_str();
  command->callback([options, &world] { runBench(*options, world); });
}

}  // namespace amrstream::cli
