#include "trace_job.hpp"

#include <fmt/format.h>

#include <map>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "flow/line_plan.hpp"
#include "flow/seed_strategies.hpp"
#include "formats/load_input.hpp"
#include "progress.hpp"
#include "trace_settings.hpp"
#include "util/host_memory.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

const char* reasonName(int reason) {
  switch (reason) {
    case AMRSTREAM_REASON_OUT_OF_DOMAIN:
      return "out of domain";
    case AMRSTREAM_REASON_UNEXPECTED_VALUE:
      return "invalid sample";
    case AMRSTREAM_REASON_MAX_LENGTH:
      return "max length";
    case AMRSTREAM_REASON_MAX_STEPS:
      return "max steps";
    case AMRSTREAM_REASON_STAGNATION:
      return "stagnation";
    case AMRSTREAM_REASON_MAX_TIME:
      return "max time";
    default:
      return "unknown";
  }
}

namespace {

glm::dvec3 corner(const std::vector<double>& v, int which) {
  return glm::dvec3(v[3 * which], v[3 * which + 1], v[3 * which + 2]);
}

// The seed box: --seed-box, checked against the domain, or the domain itself.
std::pair<glm::dvec3, glm::dvec3> seedBox(const TraceJobOptions& o,
                                          const flow::VectorVolume& volume) {
  const glm::dvec3 domainLo = flow::domainLower(volume), domainHi = flow::domainUpper(volume);
  if (o.seedBox.empty()) return {domainLo, domainHi};
  const glm::dvec3 lo = corner(o.seedBox, 0), hi = corner(o.seedBox, 1);
  if (glm::any(glm::greaterThan(lo, hi)))
    throw InputError("--seed-box", "the lower corner must not exceed the upper corner");
  if (glm::any(glm::lessThan(lo, domainLo)) || glm::any(glm::greaterThan(hi, domainHi)))
    throw InputError(
        "--seed-box",
        fmt::format("the box reaches outside the domain [{:g}, {:g}) x [{:g}, "
                    "{:g}) x [{:g}, {:g})",
                    domainLo.x, domainHi.x, domainLo.y, domainHi.y, domainLo.z, domainHi.z));
  return {lo, hi};
}

// The periodic axes the input declares (none when it says nothing).
flow::PeriodicAxes filePeriodicAxes(const bricks::AmrField& field) {
  return field.info().periodicKnown ? field.info().periodic : flow::PeriodicAxes{};
}

flow::Direction parseDirection(const std::string& name) {
  if (name == "forward") return flow::Direction::Forward;
  if (name == "backward") return flow::Direction::Backward;
  return flow::Direction::Both;
}

// --periodic: "auto" (what the file says), "none", or the periodic axes, e.g. "x,y,z" or "xz".
flow::PeriodicAxes periodicAxes(const std::string& request, const bricks::AmrField& field) {
  flow::PeriodicAxes axes{};
  if (request == "auto") return filePeriodicAxes(field);
  if (request == "none") return axes;
  for (const char c : request) {
    if (c == ',') continue;
    const auto axis = std::string_view("xyz").find(char(std::tolower(static_cast<unsigned char>(c))));
    if (axis == std::string_view::npos)
      throw InputError("--periodic", fmt::format("'{}' is not auto, none or a list of the axes "
                                                 "x, y and z",
                                                 request));
    axes[axis] = true;
  }
  return axes;
}

std::string axesText(const flow::PeriodicAxes& axes) {
  std::string text;
  for (int a = 0; a < 3; ++a)
    if (axes[a]) text += (text.empty() ? "" : ",") + std::string(1, "xyz"[a]);
  return text;
}

std::string directionText(flow::Direction direction) {
  switch (direction) {
    case flow::Direction::Forward:
      return "forward";
    case flow::Direction::Backward:
      return "backward";
    case flow::Direction::Both:
      break;
  }
  return "both directions";
}

}  // namespace

flow::SeedList chooseSeeds(const TraceJobOptions& o, const bricks::AmrField& field,
                           const flow::VectorVolume& volume, std::string& description) {
  if (!o.seedsFile.empty()) {
    description = o.seedsFile;
    return flow::readSeedFile(o.seedsFile);
  }
  if (!o.seedLine.empty()) {
    description = "a rake (--seed-line)";
    return flow::seedsAlongLine(corner(o.seedLine, 0), corner(o.seedLine, 1), o.count);
  }
  if (!o.seedDensity.empty()) {
    description = fmt::format("random cells with {} at or above its {:g}th percentile{} (seed {})",
                              o.seedDensity, o.seedPercentile,
                              o.seedWeighted ? ", weighted by it" : "", o.seed);
    return flow::seedsInDensestCells(
        field, {o.seedDensity, o.seedPercentile, o.seedWeighted, o.count, o.seed});
  }
  auto [lo, hi] = seedBox(o, volume);
  // Keep seeds off the domain's open upper faces, where rounding to float could put them.
  hi = glm::min(hi, flow::domainUpper(volume) - 1e-4 * volume.transform.spacing);
  if (!o.seedGrid.empty()) {
    const glm::ivec3 counts(o.seedGrid[0], o.seedGrid[1], o.seedGrid[2]);
    if (glm::any(glm::lessThan(counts, glm::ivec3(1))))
      throw InputError("--seed-grid", "every count must be at least 1");
    description = fmt::format("a {}x{}x{} grid in a box", counts.x, counts.y, counts.z);
    return flow::seedsOnGrid(lo, hi, counts);
  }
  description = fmt::format("random (seed {}) in a box", o.seed);
  return flow::randomSeedsInBox(lo, hi, o.count, o.seed);
}

PreparedInput prepareInput(const TraceJobOptions& o, bool withSeeds) {
  Stopwatch clock;
  PreparedInput input;
  input.cells.emplace(formats::loadInput(o.dataset.input, o.dataset.generator));
  const bricks::AmrField& field = input.field();
  input.info = field.info();
  input.source = field.source();
  const double loadSeconds = clock.seconds();
  const flow::VectorChannels vector = flow::chooseVectorChannels(field, o.vector);
  fmt::print("input      {}: {} cells, levels {}..{}, vector {} = ({}, {}, {}){} [{:.2f} s]\n",
             field.source(), withCommas(field.cellCount()),
             field.info().fileLevel(field.coarsestLevel()),
             field.info().fileLevel(field.finestLevel()), vector.name, vector.channels[0],
             vector.channels[1], vector.channels[2], bricks::timeAndUnitsClause(field.info()),
             loadSeconds);

  flow::VolumeOptions volumeOptions;
  volumeOptions.periodic = periodicAxes(o.periodic, field);
  volumeOptions.pointData = flow::choosePointData(field, vector, o.pointData);
  flow::VolumeBuildTimes times;
  input.volume = flow::buildVectorVolume(field, vector, volumeOptions, &times);
  const flow::VectorVolume& volume = input.volume;
  const std::size_t images = volume.bricks.size() - volume.originalBrickCount;
  fmt::print("structure  {} bricks{} [{:.2f} s], {} regions [{:.2f} s]\n",
             withCommas(volume.originalBrickCount),
             images > 0 ? fmt::format(" + {} periodic images ({})", withCommas(images),
                                      axesText(volume.periodic))
                        : std::string(),
             times.bricks, withCommas(volume.regions.regions.size()), times.regions);
  if (!withSeeds) return input;

  std::string pointData;
  for (const std::string& name : volume.channelNames) pointData += (pointData.empty() ? "" : ", ") + name;
  if (o.vorticity) pointData += std::string(pointData.empty() ? "" : ", ") + "vorticity";
  fmt::print("point data {}\n", pointData.empty() ? "none" : pointData);

  std::string& seedDescription = input.seedDescription;
  input.seeds = chooseSeeds(o, field, volume, seedDescription);
  flow::SeedList& seeds = input.seeds;
  flow::closeUpperFaces(volume, seeds);
  flow::checkSeedsInDomain(volume, seeds);
  if (!o.seedsOut.empty()) flow::writeSeedFile(o.seedsOut, seeds);

  flow::TraceOptions& options = input.options;
  options.stepMode = parseStepMode(o.stepMode);
  options.stepSize = chooseStepSize(options.stepMode, o.stepSize, volume);
  options.maxSteps = o.steps;
  options.keepHistory = true;
  options.terminalSpeed = o.terminalSpeed;
  if (!(o.maxLength >= 0.0f)) throw InputError("--max-length", "must be 0 (no limit) or positive");
  if (!(o.maxTime >= 0.0f)) throw InputError("--max-time", "must be 0 (no limit) or positive");
  options.maxLength = o.maxLength;
  options.maxTime = o.maxTime;
  options.direction = parseDirection(o.direction);
  options.vorticity = o.vorticity;
  options.memoryBudget = o.memoryBudget;
  options.maxResultBytes = static_cast<std::uint64_t>(kTraceMemoryShare * physicalMemoryBytes());
  fmt::print("seeds      {} from {}{}\n", withCommas(seeds.points.size()), seedDescription,
             o.seedsOut.empty() ? "" : ", written to " + o.seedsOut);
  std::string limits;
  if (o.maxLength > 0.0f) limits += fmt::format(", length <= {:g}", o.maxLength);
  if (o.maxTime > 0.0f) limits += fmt::format(", |time| <= {:g}", o.maxTime);
  fmt::print("stepping   mode {}, h = {:g}, {}, at most {} steps{}\n", o.stepMode,
             options.stepSize, directionText(options.direction), o.steps, limits);
  return input;
}

flow::StoredTraces runTraces(const TraceJobOptions& o, PreparedInput& input,
                             HostValues hostValues) {
  const flow::SeedList& seeds = input.seeds;
  TraceReport& report = input.report;
  flow::StoredTraces stored = [&] {
    // Progress counts seeds: lines finished, scaled by the lines per seed.
    Progress progress("tracing", seeds.points.size());
    return traceWithBackend(
        o.backend, input.volume, seeds.points, input.options,
        [&](std::size_t done, std::size_t lines) {
          progress.update(done * seeds.points.size() / std::max<std::size_t>(1, lines));
        },
        &report, hostValues);
  }();
  const double traceSeconds = report.traceSeconds;
  const flow::TraceSet& traces = stored.lines();

  std::size_t steps = 0;
  std::map<int, std::size_t> reasons;
  for (std::size_t i = 0; i < traces.lineCount(); ++i) {
    steps += traces.steps[i];
    ++reasons[traces.reasons[i]];
  }
  std::string histogram;
  for (const auto& [reason, count] : reasons)
    histogram += fmt::format("{}{} ({}): {}", histogram.empty() ? "" : ", ", reasonName(reason),
                             reason, withCommas(count));
  fmt::print("steps      {} taken in {} lines, {:.1f} per line\n", withCommas(steps),
             withCommas(traces.lineCount()),
             double(steps) / double(std::max<std::size_t>(1, traces.lineCount())));
  fmt::print("reasons    {}\n", histogram);
  fmt::print("time       {:.3f} s tracing, {:.3g} particle-steps/s{}\n", traceSeconds,
             double(steps) / std::max(traceSeconds, 1e-9),
             report.setupSeconds > 0.0
                 ? fmt::format(" (device setup {:.2f} s before it)", report.setupSeconds)
                 : std::string());
  return stored;
}

void addTraceJobOptions(CLI::App& app, TraceJobOptions& job, std::size_t defaultCount) {
  CLI::App* command = &app;
  TraceJobOptions* options = &job;
  options->count = defaultCount;
  addDatasetOptions(*command, options->dataset, "--gen-seed");
  command->add_option("--vector", options->vector,
                      "three channels forming the vector, e.g. velx,vely,velz "
                      "(default: the velocity, else the magnetic field)");
  auto* seedsFile =
      command
          ->add_option("--seeds", options->seedsFile, "file of seed points, one 'x y z' per line")
          ->check(CLI::ExistingFile);
  command
      ->add_option("--seed-box", options->seedBox,
                   "random seeds in this box: x0,y0,z0,x1,y1,z1 (default: the domain)")
      ->delimiter(',')
      ->expected(6)
      ->excludes(seedsFile);
  auto* seedLine = command
                       ->add_option("--seed-line", options->seedLine,
                                    "a rake of --count seeds from x0,y0,z0 to x1,y1,z1")
                       ->delimiter(',')
                       ->expected(6)
                       ->excludes(seedsFile);
  command
      ->add_option("--seed-grid", options->seedGrid,
                   "a regular NX,NY,NZ grid in the seed box instead of random seeds (a box of "
                   "zero thickness with count 1 on that axis is a plane)")
      ->delimiter(',')
      ->expected(3)
      ->excludes(seedsFile)
      ->excludes(seedLine);
  auto* seedGrid = command->get_option("--seed-grid");
  auto* seedDensity =
      command
          ->add_option("--seed-density", options->seedDensity,
                       "the paper's seeding: random points in random cells where this scalar is "
                       "at or above --seed-percentile")
          ->excludes(seedsFile)
          ->excludes(seedLine);
  command->add_option("--seed-percentile", options->seedPercentile, "see --seed-density")
      ->capture_default_str()
      ->needs(seedDensity);
  command
      ->add_flag("--seed-weighted", options->seedWeighted,
                 "with --seed-density: pick cells with probability proportional to the scalar")
      ->needs(seedDensity);
  command->add_option("--seeds-out", options->seedsOut,
                      "write the seeds used to this file, so the run can be repeated with --seeds");
  command
      ->add_option("--count", options->count,
                   "number of seeds (random, along --seed-line, or of --seed-density)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber)
      ->excludes(seedsFile)
      ->excludes(seedGrid);
  command->add_option("--seed", options->seed, "random seed for the seed points")
      ->capture_default_str()
      ->excludes(seedsFile);
  command->add_option("--steps", options->steps, "maximum integration steps per trace")
      ->capture_default_str();
  command->add_option("--step-size", options->stepSize,
                      "h: in cell widths (cell, arc) or physical time (time; default 1/4 of the "
                      "finest cell crossed at the maximum speed) [default 0.25]");
  command
      ->add_option("--step-mode", options->stepMode,
                   "cell: RK4 on w(x)v(x) (paper); time: fixed dt; arc: unit speed")
      ->capture_default_str()
      ->check(CLI::IsMember({"cell", "time", "arc"}));
  command
      ->add_option("--direction", options->direction,
                   "integration direction: forward, backward, or both (two lines per seed, as "
                   "ParaView's Stream Tracer)")
      ->capture_default_str()
      ->check(CLI::IsMember({"forward", "backward", "both"}));
  command
      ->add_option("--point-data", options->pointData,
                   "channels sampled at every trace point: all (every channel but the vector's), "
                   "none, or NAME,NAME,...")
      ->capture_default_str();
  command->add_flag("--vorticity", options->vorticity,
                    "also write Vorticity, Rotation and AngularVelocity (as vtkStreamTracer)");
  command
      ->add_option("--periodic", options->periodic,
                   "periodic axes: auto (as the file says), none, or a list such as x,y,z")
      ->capture_default_str();
  command
      ->add_option("--terminal-speed", options->terminalSpeed,
                   "stop where the speed falls below this")
      ->capture_default_str();
  command
      ->add_option("--max-length", options->maxLength,
                   "stop before the trace's physical length passes this (0: no limit)")
      ->capture_default_str();
  command
      ->add_option("--max-time", options->maxTime,
                   "stop where |IntegrationTime| reaches this, the last step shortened to end "
                   "on it (0: no limit)")
      ->capture_default_str();
  command
      ->add_option("--memory-budget", options->memoryBudget,
                   "bytes the tracing rounds may use on the device and for the host copies, "
                   "e.g. 512M or 2G (the collected traces come on top); 0: automatic, 256M to 2G")
      ->transform(CLI::AsSizeValue(false))
      ->capture_default_str();
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
