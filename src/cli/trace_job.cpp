#include "trace_job.hpp"

#include <fmt/format.h>

#include <limits>
#include <map>

#include "amrstream/dataset.hpp"
#include "amrstream/field.hpp"
#include "dataset_files.hpp"
#include "formats/load_input.hpp"
#include "option_checks.hpp"
#include "option_limits.hpp"
#include "output/seed_file_writer.hpp"
#include "progress.hpp"
#include "util/host_memory.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

// The most --memory-budget may ask for: the machine's memory (any count when it is unknown).
std::uint64_t hostMemoryBytes() {
  const double memory = physicalMemoryBytes();
  return memory > 0.0 ? static_cast<std::uint64_t>(memory)
                      : std::numeric_limits<std::uint64_t>::max();
}

}  // namespace

void printLine(const std::string& line) { fmt::print("{}\n", line); }

Log printLineAfter(Progress& progress) {
  return [&progress](const std::string& line) {
    progress.clear();
    printLine(line);
  };
}

std::string reasonHistogram(std::span<const std::int32_t> reasons) {
  std::map<int, std::size_t> counts;
  for (const std::int32_t reason : reasons) ++counts[reason];
  std::string histogram;
  for (const auto& [reason, count] : counts)
    histogram += fmt::format("{}{} ({}): {}", histogram.empty() ? "" : ", ", reasonName(reason),
                             reason, withCommas(count));
  return histogram;
}

RunFiles jobFiles(const TraceJobOptions& o) {
  checkBuiltinSize(o.dataset);
  checkSeedRequest(o.seeds);
  RunFiles files;
  files.addInputs(datasetFiles(o.dataset.input));
  if (!o.seeds.file.empty()) files.addInput(o.seeds.file);
  if (!o.seedsOut.empty()) files.addOutput("--seeds-out", o.seedsOut);
  return files;
}

PreparedInput prepareInput(const TraceJobOptions& o, bool withSeeds, CellsAfter after,
                           InputShare* share) {
  Stopwatch clock;
  PreparedInput input;
  // Deferred: the channels stay in their files until the volume's layout and the seeds are made
  // and the cells freed, so one channel at a time is in memory beside the volume (.exa inputs).
  const bool deferred = after == CellsAfter::Release && withSeeds && !share;
  DeferredDataset data =
      deferred
          ? loadDeferred(o.dataset.input, o.dataset.generator)
          : DeferredDataset{std::make_shared<Dataset>(formats::loadInput(
                                o.dataset.input, o.dataset.generator,
                                share ? &share->window : nullptr, share ? &share->read : nullptr)),
                            {},
                            {}};
  if (!deferred) data.catalog = flow::catalogOf(*data.cells);
  const bricks::AmrField& cells = *data.cells;
  input.info = cells.info();
  input.source = cells.source();
  const double loadSeconds = clock.seconds();
  const FieldPlan plan = planField(data.catalog, cells.info(), o.field);
  const flow::VectorChannels& vector = plan.vector;
  fmt::print("input      {}: {} cells, levels {}..{}, vector {} = ({}, {}, {}){} [{:.2f} s]\n",
             cells.source(), withCommas(cells.cellCount()),
             cells.info().fileLevel(cells.coarsestLevel()),
             cells.info().fileLevel(cells.finestLevel()), vector.name, vector.channels[0],
             vector.channels[1], vector.channels[2], bricks::timeAndUnitsClause(cells.info()),
             loadSeconds);
  flow::VolumeBuildTimes times;
  if (deferred) {
    input.volume = flow::buildCellLayout(cells, plan.volume, &times);
    // The seeds' density channel after the layout, whose build needs memory beside the cells.
    const std::string& density = o.seeds.density;
    if (!density.empty() && !cells.findChannel(density)) {
      data.catalog.require(density);  // listing every channel when it is absent
      data.channels(density, [&](std::span<const float> values) {
        data.cells->addChannel({density, {values.begin(), values.end()}});
      });
    }
    input.seeds = chooseSeeds(o.seeds, domainOf(input.volume), &cells, input.seedDescription);
    data.cells.reset();  // the cells' corners and levels, and the channels loaded for the seeds
    flow::fillVolumeValues(input.volume, vector, plan.volume, input.source, data.channels, &times);
  } else if (share && share->layout) {
    // The cells' layout, built from the same cells before their values were read.
    input.volume = std::move(*share->layout);
    share->layout.reset();
    times = share->layoutTimes;
    flow::fillVolumeValues(input.volume, cells, vector, plan.volume, &times);
    input.cells = data.cells;
  } else {
    input.volume = flow::buildVectorVolume(cells, vector, plan.volume, &times);
    input.cells = data.cells;
  }
  const flow::VectorVolume& volume = input.volume;
  const std::size_t images = volume.bricks.size() - volume.originalBrickCount;
  fmt::print("structure  {} bricks{} [{:.2f} s], {} regions [{:.2f} s]{}\n",
             withCommas(volume.originalBrickCount),
             images > 0 ? fmt::format(" + {} periodic images ({})", withCommas(images),
                                      axesText(volume.periodic))
                        : std::string(),
             times.bricks, withCommas(volume.regions.regions.size()), times.regions,
             volume.interpolant == flow::Interpolant::Linear
                 ? fmt::format(", linear interpolant's gradients [{:.2f} s]", times.gradients)
                 : std::string());
  if (!withSeeds) return input;

  std::string pointData;
  for (const std::string& name : volume.channelNames)
    pointData += (pointData.empty() ? "" : ", ") + name;
  if (o.trace.vorticity) pointData += std::string(pointData.empty() ? "" : ", ") + "vorticity";
  fmt::print("point data {}\n", pointData.empty() ? "none" : pointData);

  if (share && !o.seeds.density.empty()) {
    share->markOwned(*input.cells, share->owned);
    share->cells.owned = share->owned;
  }
  if (!deferred)
    input.seeds = chooseSeeds(o.seeds, domainOf(volume), input.cells.get(), input.seedDescription,
                              share ? &share->cells : nullptr);
  flow::SeedList& seeds = input.seeds;
  placeSeeds(volume, seeds);
  if (!o.seedsOut.empty()) output::writeSeedFile(o.seedsOut, seeds);

  input.options = traceOptions(o.trace, volume);
  const flow::TraceOptions& options = input.options;
  fmt::print("seeds      {} from {}{}\n", withCommas(seeds.points.size()), input.seedDescription,
             o.seedsOut.empty() ? "" : ", written to " + o.seedsOut);
  std::string limits;
  if (o.trace.maxLength > 0.0f) limits += fmt::format(", length <= {:g}", o.trace.maxLength);
  if (o.trace.maxTime > 0.0f) limits += fmt::format(", |time| <= {:g}", o.trace.maxTime);
  const std::string integrator =
      options.integrator == flow::Integrator::Rk45
          ? fmt::format("rk45 (tolerance {:g}, steps {:g} .. {:g})", options.tolerance,
                        options.minStep, options.maxStep)
          : integratorName(options.integrator);
  fmt::print("stepping   mode {}, h = {:g}, {}, {}, at most {} steps{}\n", o.trace.stepMode,
             options.stepSize, integrator,
             options.direction == flow::Direction::Both ? "both directions"
                                                        : directionName(options.direction),
             o.trace.steps, limits);
  return input;
}

flow::StoredTraces traceSeeds(const TraceJobOptions& o, PreparedInput& input,
                              HostValues hostValues) {
  const flow::SeedList& seeds = input.seeds;
  // Progress counts seeds: lines finished, scaled by the lines per seed.
  Progress progress("tracing", seeds.points.size());
  return trace(
      o.backend, input.volume, seeds.points, input.options,
      [&](std::size_t done, std::size_t lines) {
        progress.update(done * seeds.points.size() / std::max<std::size_t>(1, lines));
      },
      &input.report, hostValues, printLineAfter(progress));
}

void printTraceSummary(const flow::TraceSet& traces, const TraceReport& report) {
  std::size_t steps = 0;
  for (const std::uint32_t lineSteps : traces.steps) steps += lineSteps;
  fmt::print("steps      {} taken in {} lines, {:.1f} per line\n", withCommas(steps),
             withCommas(traces.lineCount()),
             double(steps) / double(std::max<std::size_t>(1, traces.lineCount())));
  fmt::print("reasons    {}\n", reasonHistogram(traces.reasons));
  fmt::print("time       {:.3f} s tracing, {:.3g} particle-steps/s{}\n", report.traceSeconds,
             double(steps) / std::max(report.traceSeconds, 1e-9),
             report.setupSeconds > 0.0
                 ? fmt::format(" (device setup {:.2f} s before it)", report.setupSeconds)
                 : std::string());
}

flow::StoredTraces runTraces(const TraceJobOptions& o, PreparedInput& input,
                             HostValues hostValues) {
  flow::StoredTraces stored = traceSeeds(o, input, hostValues);
  printTraceSummary(stored.lines(), input.report);
  return stored;
}

std::unique_ptr<HeldTraces> runTracesForWriting(const TraceJobOptions& o, PreparedInput& input,
                                                TraceStore store, HostValues hostValues) {
  const flow::SeedList& seeds = input.seeds;
  Progress progress("tracing", seeds.points.size());
  std::unique_ptr<HeldTraces> held = traceForWriting(
      o.backend, input.volume, seeds.points, input.options, store,
      [&](std::size_t done, std::size_t lines) {
        progress.update(done * seeds.points.size() / std::max<std::size_t>(1, lines));
      },
      &input.report, hostValues, printLineAfter(progress));
  printTraceSummary(held->view().lines(), input.report);
  return held;
}

void addSeedOptions(CLI::App& app, SeedRequest& seeds, std::string* seedsOut) {
  CLI::App* command = &app;
  auto* seedsFile =
      command->add_option("--seeds", seeds.file, "file of seed points, one 'x y z' per line")
          ->check(regularFile());
  command
      ->add_option("--seed-box", seeds.box,
                   "random seeds in this box: x0,y0,z0,x1,y1,z1 (default: the domain)")
      ->delimiter(',')
      ->expected(6)
      ->check(finiteFloat())
      ->excludes(seedsFile);
  auto* seedLine = command
                       ->add_option("--seed-line", seeds.line,
                                    "a rake of --count seeds from x0,y0,z0 to x1,y1,z1")
                       ->delimiter(',')
                       ->expected(6)
                       ->check(finiteFloat())
                       ->excludes(seedsFile);
  command
      ->add_option("--seed-grid", seeds.grid,
                   "a regular NX,NY,NZ grid in the seed box instead of random seeds (a box of "
                   "zero thickness with count 1 on that axis is a plane)")
      ->delimiter(',')
      ->expected(3)
      ->check(countIn(1, kMaxSeedCount))
      ->excludes(seedsFile)
      ->excludes(seedLine);
  auto* seedGrid = command->get_option("--seed-grid");
  auto* seedDensity =
      command
          ->add_option("--seed-density", seeds.density,
                       "the paper's seeding: random points in random cells where this scalar is "
                       "at or above --seed-percentile")
          ->excludes(seedsFile)
          ->excludes(seedLine);
  command->add_option("--seed-percentile", seeds.percentile, "see --seed-density")
      ->capture_default_str()
      ->check(numberIn(0.0, 100.0))
      ->needs(seedDensity);
  command
      ->add_flag("--seed-weighted", seeds.weighted,
                 "with --seed-density: pick cells with probability proportional to the scalar")
      ->needs(seedDensity);
  if (seedsOut != nullptr)
    command->add_option("--seeds-out", *seedsOut,
                        "write the seeds used to this file, so the run can be repeated with "
                        "--seeds");
  command
      ->add_option("--count", seeds.count,
                   "number of seeds (random, along --seed-line, or of --seed-density)")
      ->capture_default_str()
      ->check(countIn(1, kMaxSeedCount))
      ->excludes(seedsFile)
      ->excludes(seedGrid);
  command->add_option("--seed", seeds.seed, "random seed for the seed points")
      ->capture_default_str()
      ->check(countIn(0, std::numeric_limits<std::uint64_t>::max()))
      ->excludes(seedsFile);
}

void addFieldOptions(CLI::App& app, FieldOptions& field) {
  CLI::App* command = &app;
  command->add_option("--vector", field.vector,
                      "three channels forming the vector, e.g. velx,vely,velz "
                      "(default: the velocity, else the magnetic field)");
  command
      ->add_option("--point-data", field.pointData,
                   "channels sampled at every trace point: all (every channel but the vector's), "
                   "none, or NAME,NAME,...")
      ->capture_default_str();
  command
      ->add_option("--periodic", field.periodic,
                   "periodic axes: auto (as the file says), none, or a list such as x,y,z")
      ->capture_default_str();
  command
      ->add_option("--interpolant", field.interpolant,
                   "tent: the paper's tent basis functions (exact for constants); linear: tent "
                   "weights over each cell's least-squares linear model (exact for linear fields "
                   "across level jumps)")
      ->capture_default_str()
      ->check(CLI::IsMember({"tent", "linear"}));
}

void addTraceJobOptions(CLI::App& app, TraceJobOptions& job, std::size_t defaultCount) {
  CLI::App* command = &app;
  TraceJobOptions* options = &job;
  options->seeds.count = defaultCount;
  addDatasetOptions(*command, options->dataset, "--gen-seed");
  addFieldOptions(*command, options->field);
  addSeedOptions(*command, options->seeds, &options->seedsOut);
  command->add_option("--steps", options->trace.steps, "maximum integration steps per trace")
      ->capture_default_str()
      ->check(countIn(0, kMaxSteps));
  command
      ->add_option("--step-size", options->trace.stepSize,
                   "h: in cell widths (cell, arc) or physical time (time; default 1/4 of the "
                   "finest cell crossed at the maximum speed) [default 0.25]")
      ->check(positiveFloat());
  command
      ->add_option("--step-mode", options->trace.stepMode,
                   "arc: steps of h cell widths whatever the speed; cell: the paper's, on "
                   "w(x)v(x), so h depends on the vector's units; time: fixed dt")
      ->capture_default_str()
      ->check(CLI::IsMember({"cell", "time", "arc"}));
  command
      ->add_option("--integrator", options->trace.integrator,
                   "rk4 (the paper's), rk45 (Dormand-Prince with error control), rk2 or euler")
      ->capture_default_str()
      ->check(CLI::IsMember({"rk4", "rk45", "rk2", "euler"}));
  command
      ->add_option("--tolerance", options->trace.tolerance,
                   "rk45: the error allowed per step, in finest cell widths of its region")
      ->capture_default_str()
      ->check(positiveFloat());
  command
      ->add_option("--min-step", options->trace.minStep,
                   "rk45: the smallest step, in --step-size's units [default: the first step / "
                   "100]")
      ->check(positiveFloat());
  command
      ->add_option("--max-step", options->trace.maxStep,
                   "rk45: the largest step, in --step-size's units [default: the first step x 4]")
      ->check(positiveFloat());
  command
      ->add_option("--direction", options->trace.direction,
                   "integration direction: forward, backward, or both (two lines per seed, as "
                   "ParaView's Stream Tracer)")
      ->capture_default_str()
      ->check(CLI::IsMember({"forward", "backward", "both"}));
  command->add_flag("--vorticity", options->trace.vorticity,
                    "also write Vorticity, Rotation and AngularVelocity (as vtkStreamTracer)");
  command
      ->add_option("--terminal-speed", options->trace.terminalSpeed,
                   "stop where the speed falls below this")
      ->capture_default_str()
      ->check(nonNegativeFloat());
  command
      ->add_option("--max-length", options->trace.maxLength,
                   "stop before the trace's physical length passes this (0: no limit)")
      ->capture_default_str()
      ->check(nonNegativeFloat());
  command
      ->add_option("--max-time", options->trace.maxTime,
                   "stop where |IntegrationTime| reaches this, the last step shortened to end "
                   "on it (0: no limit)")
      ->capture_default_str()
      ->check(nonNegativeFloat());
  command
      ->add_option("--memory-budget", options->trace.memoryBudget,
                   "bytes the tracing rounds may use (a GPU's round buffers, or the CPU's), "
                   "e.g. 512M or 2G (the collected traces come on top); 0: automatic, 256M to "
                   "8G on a GPU, 2G on the CPU")
      ->transform(CLI::AsSizeValue(false))
      ->check(countIn(0, hostMemoryBytes()))
      ->capture_default_str();
  command
      ->add_option("--cpu-tail", options->trace.cpuTail,
                   "on a GPU: once a round leaves this many running lines or fewer, the CPU "
                   "finishes them on all cores (a lone line's step is faster there); 0: never. "
                   "Without history the GPU then runs rounds of an eighth of --steps, at least "
                   "1000; the points wait in host memory")
      ->capture_default_str()
      ->check(countIn(0, kMaxLineCount));
  command
      ->add_option("--backend", options->backend.backend,
                   "auto (rayquery, else pipeline, else compute, else cpu), rayquery, "
                   "pipeline, compute or cpu")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "rayquery", "pipeline", "compute", "cpu"}));
  command->add_option("--device", options->backend.device,
                      "the Vulkan device whose name contains this (see `amrstream devices`)");
}

}  // namespace amrstream::cli
