#include "bench_command.hpp"

#include <limits>
#include <memory>

#include "amrstream/bench.hpp"
#include "amrstream/run_files.hpp"
#include "amrstream/seeding.hpp"
#include "console.hpp"
#include "dataset_options.hpp"
#include "option_checks.hpp"
#include "option_limits.hpp"

namespace amrstream::cli {

namespace {

// What is measured: the backends, particle counts, modes and repeats.
void addRunOptions(CLI::App& command, BenchRequest& options) {
  command
      .add_option("--backends", options.backends,
                  "backends in run order; those the device lacks are noted and skipped")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"rayquery", "pipeline", "compute", "cpu"}));
  command
      .add_option("--particles", options.particles,
                  "particle counts, comma-separated [default: 1024,2048,...,1048576]")
      ->delimiter(',')
      ->check(countIn(1, kMaxSeedCount));
  command
      .add_option("--cpu-max-particles", options.cpuMaxParticles,
                  "the CPU path runs counts up to this")
      ->capture_default_str()
      ->check(countIn(0, kMaxSeedCount));
  command
      .add_option("--mode", options.mode,
                  "endpoints (keep only the last point), history (every step), or both")
      ->capture_default_str()
      ->check(CLI::IsMember({"endpoints", "history", "both"}));
  command
      .add_option("--history-points", options.historyPoints,
                  "history rows storing more trace points than this are skipped")
      ->capture_default_str()
      ->check(countIn(1, kMaxHistoryPoints));
  command.add_option("--repeats", options.repeats, "runs per row; the fastest is kept")
      ->capture_default_str()
      ->check(countIn(1, kMaxRepeats));
  command.add_option("--steps", options.steps, "maximum integration steps per particle")
      ->capture_default_str()
      ->check(countIn(1, kMaxSteps));
  command
      .add_option("--round-steps", options.roundSteps,
                  "steps per round on the GPU, the lines that ended dropped between rounds "
                  "(0: every step in one round without history, as many as the rounds' "
                  "memory holds with it)")
      ->capture_default_str()
      ->check(countIn(0, kMaxSteps));
  command
      .add_option("--cpu-tail", options.cpuTailLines,
                  "GPU rows: once a round leaves this many running lines or fewer, the CPU "
                  "finishes them on all cores (0: never; without history the GPU then runs "
                  "rounds of an eighth of the steps, at least 1000)")
      ->capture_default_str()
      ->check(countIn(0, kMaxLineCount));
}

// How each particle steps.
void addSteppingOptions(CLI::App& command, BenchRequest& options) {
  command
      .add_option("--step-size", options.stepSize,
                  "h: in cell widths (cell, arc) or physical time (time) [default 0.25]")
      ->check(positiveFloat());
  command.add_option("--interpolant", options.interpolant, "tent (paper) or linear")
      ->capture_default_str()
      ->check(CLI::IsMember({"tent", "linear"}));
  command.add_option("--step-mode", options.stepMode, "cell (paper), time or arc")
      ->capture_default_str()
      ->check(CLI::IsMember({"cell", "time", "arc"}));
}

// Where the particles start.
void addSeedOptions(CLI::App& command, BenchRequest& options) {
  auto* seedsFile = command
                        .add_option("--seeds", options.seedsFile,
                                    "seed points, one 'x y z' per line (at least the largest "
                                    "particle count)")
                        ->check(regularFile());
  command
      .add_option("--seed-density", options.seedDensity,
                  "the scalar whose densest cells get the seeds [default: dens, else the first "
                  "scalar outside the vector]")
      ->excludes(seedsFile);
  command
      .add_option("--seed-percentile", options.seedPercentile,
                  "candidate cells are at or above this percentile of the scalar")
      ->capture_default_str()
      ->check(numberIn(0.0, 100.0))
      ->excludes(seedsFile);
  command.add_option("--seed", options.seed, "random seed for the seed points")
      ->capture_default_str()
      ->check(countIn(0, std::numeric_limits<std::uint64_t>::max()))
      ->excludes(seedsFile);
}

// The device and the GPU kernels' variants.
void addKernelOptions(CLI::App& command, BenchRequest& options) {
  command.add_option("--device", options.device,
                     "the Vulkan device whose name contains this (see `amrstream devices`)");
  command
      .add_option("--region-hint", options.regionHint,
                  "GPU samples test the previous sample's region before locating: on, off "
                  "(every sample runs the point location) or each backend's default (on)")
      ->capture_default_str()
      ->check(CLI::IsMember({"default", "on", "off"}));
  command
      .add_option("--dual-values", options.dualValues,
                  "GPU kernels read the vector as dual cells, the 8 values of each 2x2x2 block "
                  "of a brick together (8 times the values' memory; tent interpolant): on, off "
                  "or the default")
      ->capture_default_str()
      ->check(CLI::IsMember({"default", "on", "off"}));
  command
      .add_option("--spread-threads", options.spreadThreads,
                  "GPU rounds of fewer lines than this give each line up to 32 invocations, "
                  "the first tracing it, at most this many in all (0: one invocation a line; "
                  "-1: the default, 131072 for compute and rayquery on GPUs, 65536 for pipeline, "
                  "0 on CPU devices)")
      ->capture_default_str()
      ->check(CLI::Range(std::int64_t(-1), std::int64_t(kMaxLineCount)));
  command
      .add_option("--seed-order", options.seedOrder,
                  "spatial: GPU threads take seeds in Morton order of their positions; given: "
                  "in the order drawn")
      ->capture_default_str()
      ->check(CLI::IsMember({"spatial", "given"}));
}

}  // namespace

void addBenchCommand(CLI::App& app, const std::string& commandLine, const MpiWorld& world) {
  auto options = std::make_shared<BenchRequest>();
  options->commandLine = commandLine;
  CLI::App* command = app.add_subcommand(
      "bench", "the paper's performance experiment: particle-steps per second of every backend");
  addDatasetOptions(*command, options->dataset, "--gen-seed", DeclaresUnits::No);
  command->add_option("--vector", options->vector, "three channels forming the vector");
  addRunOptions(*command, *options);
  addSteppingOptions(*command, *options);
  addSeedOptions(*command, *options);
  addKernelOptions(*command, *options);
  command->add_option("--json", options->json, "where to write the results")->capture_default_str();
  command->callback([options, &world] {
    const BenchRequest& o = *options;
    const Console console;
    runBench(
        world, o,
        [&o] {
          RunFiles files;
          files.addInputs(datasetFiles(o.dataset.input));
          if (!o.seedsFile.empty()) files.addInput(o.seedsFile);
          files.addOutput("--json", o.json);
          requireOutputExtension("--json", o.json, {".json"}, "JSON");
        },
        console);
  });
}

}  // namespace amrstream::cli
