#include "amrstream/pathlines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <memory>
#include <set>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "amrstream/dataset.hpp"
#include "amrstream/error.hpp"
#include "amrstream/settings.hpp"
#include "amrstream/version.hpp"
#include "api/device.hpp"
#include "api/field_plan.hpp"
#include "api/handles.hpp"
#include "api/job_state.hpp"
#include "api/seed_choice.hpp"
#include "api/traces_impl.hpp"
#include "flow/pathline_tracer.hpp"
#include "formats/snapshot_time.hpp"
#include "gpu/pathline_stepper.hpp"
#include "gpu/vector_probe.hpp"
#include "util/host_memory.hpp"
#include "util/host_threads.hpp"
#include "util/peak_memory.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

namespace {

struct LoadedSnapshot {
  double time = 0.0;
  std::optional<Field> field;
  std::optional<Dataset> cells;  // kept for the first only: density seeding reads them
  std::uint64_t cellCount = 0;
  double readSeconds = 0.0, buildSeconds = 0.0;
};

std::unique_ptr<LoadedSnapshot> loadSnapshot(const SnapshotFile& file, const PathlineJob& job,
                                             bool keepCells) {
  auto owned = std::make_unique<LoadedSnapshot>();
  LoadedSnapshot& loaded = *owned;
  loaded.time = file.time;
  Stopwatch clock;
  Dataset cells = load(file.path, {}, job.units);
  loaded.readSeconds = clock.seconds();
  loaded.cellCount = cells.cellCount();
  clock.restart();
  loaded.field = buildField(cells, job.field, KeepDataset::No);
  loaded.buildSeconds = clock.seconds();
  if (keepCells) loaded.cells.emplace(std::move(cells));
  return owned;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ",") + name;
  return text.empty() ? "none" : text;
}

// Every snapshot must offer what the first one traced with.
void checkLikeTheFirst(const LoadedSnapshot& s, const std::string& path,
                       const PathlineReport& report) {
  const flow::VectorVolume& v = volumeOf(*s.field);
  if (v.vectorName != report.vectorName)
    throw InputError(path, fmt::format("its vector is '{}', the first snapshot's '{}'",
                                       v.vectorName, report.vectorName));
  if (v.channelNames != report.channelNames)
    throw InputError(path, fmt::format("its point-data channels are {}, the first snapshot's {}",
                                       joined(v.channelNames), joined(report.channelNames)));
}

// Indices of the snapshots bracketing [t0, t1].
std::pair<std::size_t, std::size_t> snapshotsUsed(std::span<const SnapshotFile> series, double t0,
                                                  double t1) {
  std::size_t first = 0;
  while (first + 1 < series.size() && series[first + 1].time <= t0) ++first;
  std::size_t last = first + 1;
  while (last + 1 < series.size() && series[last].time < t1) ++last;
  return {first, last};
}

// A GPU backend's context and probe kernel, shared by the snapshots' probes.
struct GpuSampling {
  vk::Context ctx;
  gpu::TraceKernel kernel;
  gpu::PathlineStepper stepper;

  GpuSampling(const BackendRequest& request, const BackendChoice& choice)
      : ctx(createContext(request, choice)),
        kernel(gpu::createTraceKernel(ctx, choice.backend, gpu::KernelProgram::LocateProbe)),
        stepper(ctx, kernel) {}

  std::unique_ptr<gpu::VectorProbe> probe(const flow::VectorVolume& volume,
                                          PathlineReport& report) {
    Stopwatch clock;
    auto probe = std::make_unique<gpu::VectorProbe>(ctx, kernel, volume);
    report.deviceSeconds += clock.seconds();
    return probe;
  }
};

void addProbeTimes(const gpu::VectorProbe& probe, PathlineReport& report) {
  const gpu::VectorProbe::Times& t = probe.times();
  report.probeCalls += t.calls;
  report.probeWriteSeconds += t.writeSeconds;
  report.probeDeviceSeconds += t.deviceSeconds;
  report.probeReadSeconds += t.readSeconds;
}

flow::VectorBatchSampler samplerOf(gpu::VectorProbe* probe) {
  if (!probe) return {};
  return [probe](std::span<const glm::vec3> cells, std::span<flow::VectorSample> out) {
    probe->sample(cells, out);
  };
}

}  // namespace

std::vector<SnapshotFile> listSnapshots(std::span<const std::string> patterns) {
  std::vector<SnapshotFile> series;
  std::set<std::string> datasets;
  for (const std::string& file : formats::expandSnapshotPatterns(patterns)) {
    const std::string path = formats::snapshotDataset(file);
    if (!datasets.insert(path).second) continue;  // another file of a dataset already listed
    const std::optional<double> time = formats::snapshotTime(path);
    if (!time)
      throw InputError(path, "the file states no time, so it cannot take a place in a series");
    series.push_back({path, *time});
  }
  std::stable_sort(series.begin(), series.end(),
                   [](const SnapshotFile& a, const SnapshotFile& b) { return a.time < b.time; });
  for (std::size_t i = 1; i < series.size(); ++i)
    if (series[i].time == series[i - 1].time)
      throw InputError(series[i].path, fmt::format("it is at time {:g}, as {} is", series[i].time,
                                                   series[i - 1].path));
  if (series.size() < 2)
    throw InputError("pathlines",
                     fmt::format("a series needs two snapshots or more; {} given", series.size()));
  return series;
}

namespace {

// Whether a time step of h can be taken at time t: t + h must move by h (to a part in 1000).
bool resolvableAt(double t, double h) { return std::abs(((t + h) - t) - h) <= 1e-3 * h; }

// A particle steps from the start to the end time: refuses a step it can never finish with, or
// that the times cannot resolve. `given`: the user set it; else it is a tenth of the shortest
// interval between the snapshots `closest` (their paths) apart.
void checkStepCount(const flow::PathlineOptions& options, bool given,
                    const std::pair<std::string, std::string>& closest) {
  const double h = options.stepSize;
  const double steps = std::ceil((options.endTime - options.startTime) / h);
  const char* const why = given ? "" : " (the default, a tenth of the shortest interval used)";
  const std::string snapshots =
      given ? std::string()
            : fmt::format("; snapshots {} and {} are closest; give {{step_size}}", closest.first,
                          closest.second);
  if (!(steps <= settings::kSteps.most))
    throw settingError("step_size",
                       fmt::format("{:g}{} needs {:.3g} steps from t = {:g} to {:g}, more than "
                                   "the {:.0f} a particle may take{}",
                                   h, why, steps, options.startTime, options.endTime,
                                   settings::kSteps.most, snapshots));
  for (const double t : {options.startTime, options.endTime})
    if (!resolvableAt(t, h))
      throw settingError("step_size", fmt::format("{:g}{} is too small to step by at t = {:g}, "
                                                  "whose double precision cannot resolve it{}",
                                                  h, why, t, snapshots));
}

// Streaklines release every seed again every `releaseEvery`: refuses more particles than a
// trace may hold or its memory holds, or an interval the times cannot resolve. `seedCount` 0:
// the seeds are not chosen yet, and only the releases are checked.
void checkReleases(const flow::PathlineOptions& options, std::size_t seedCount,
                   std::size_t channelCount) {
  if (!(options.releaseEvery > 0.0)) return;
  const double span = options.endTime - options.startTime;
  const double releases = std::ceil(span / options.releaseEvery);
  const double particles = releases * double(std::max<std::size_t>(seedCount, 1));
  const std::string ofSeeds =
      seedCount > 0 ? fmt::format(", {:.3g} particles of {} seeds", particles, seedCount) : "";
  if (!(particles <= settings::kCount.most))
    throw settingError("release_every",
                       fmt::format("{:g} releases the seeds {:.3g} times from t = {:g} to {:g}{}, "
                                   "more than the {:.0f} particles a run may hold",
                                   options.releaseEvery, releases, options.startTime,
                                   options.endTime, ofSeeds, settings::kCount.most));
  if (!resolvableAt(options.startTime, options.releaseEvery) ||
      !resolvableAt(options.endTime, options.releaseEvery))
    throw settingError("release_every",
                       fmt::format("{:g} is too small to release by between t = {:g} and {:g}, "
                                   "whose double precision cannot resolve it",
                                   options.releaseEvery, options.startTime, options.endTime));
  if (seedCount == 0 || options.maxResultBytes == 0) return;
  // On average a particle lives half the span: its state and a point per step.
  const double points = particles * (1.0 + 0.5 * std::ceil(span / options.stepSize));
  const double bytes = particles * double(flow::PathlineTracer::kBytesPerParticle) +
                       points * double(flow::PathlineTracer::bytesPerPoint(channelCount));
  if (bytes > double(options.maxResultBytes))
    throw settingError("release_every",
                       fmt::format("{:g} makes {:.3g} particles of {} seeds with about {:.3g} "
                                   "points, which need {:.1f} GB, more than the {:.1f} GB the "
                                   "result may take",
                                   options.releaseEvery, particles, seedCount, points, bytes / 1e9,
                                   double(options.maxResultBytes) / 1e9));
}

// The tracer's options from the settings and the series, checked.
flow::PathlineOptions pathlineOptions(std::span<const SnapshotFile> series,
                                      const PathlineSettings& settings) {
  const double seriesStart = series.front().time, seriesEnd = series.back().time;
  flow::PathlineOptions options;
  options.startTime = settings.startTime.value_or(seriesStart);
  options.endTime = settings.endTime.value_or(seriesEnd);
  if (options.startTime < seriesStart || options.startTime >= seriesEnd)
    throw settingError("start_time",
                       fmt::format("{:g} is outside the series, which runs from {:g} to {:g}",
                                   options.startTime, seriesStart, seriesEnd));
  if (!(options.endTime > options.startTime))
    throw settingError("end_time", fmt::format("{:g} is not after the start time {:g}",
                                               options.endTime, options.startTime));
  if (options.endTime > seriesEnd)
    throw settingError("end_time",
                       fmt::format("{:g} is after the series, which ends at {:g} ({}): the field "
                                   "is not known after its last snapshot",
                                   options.endTime, seriesEnd, series.back().path));
  if (options.endTime == seriesEnd) options.endReason = AMRSTREAM_REASON_SERIES_END;
  const auto [first, last] = snapshotsUsed(series, options.startTime, options.endTime);
  double shortest = seriesEnd - seriesStart;
  std::pair<std::string, std::string> closest{series.front().path, series.back().path};
  for (std::size_t i = first; i < last; ++i)
    if (series[i + 1].time - series[i].time < shortest) {
      shortest = series[i + 1].time - series[i].time;
      closest = {series[i].path, series[i + 1].path};
    }
  options.stepSize = settings.stepSize.value_or(shortest / 10);
  if (!(options.stepSize > 0.0) || !std::isfinite(options.stepSize))
    throw settingError("step_size", fmt::format("{:g} is not a positive time", options.stepSize));
  checkStepCount(options, settings.stepSize.has_value(), closest);
  if (settings.releaseEvery < 0.0 || !std::isfinite(settings.releaseEvery))
    throw settingError("release_every",
                       fmt::format("{:g} is not a positive time", settings.releaseEvery));
  options.releaseEvery = settings.releaseEvery;
  options.maxResultBytes =
      settings.maxResultBytes > 0
          ? settings.maxResultBytes
          : static_cast<std::uint64_t>(kTraceMemoryShare * physicalMemoryBytes());
  checkReleases(options, 0, 0);
  return options;
}

// The backend's device and kernels, or none for the CPU (on the heap: the stepper points at the
// context and the probe kernel).
std::unique_ptr<GpuSampling> openSampling(const BackendRequest& request, PathlineReport& report,
                                          const Log& log) {
  const BackendChoice choice = chooseBackend(request, BackendUse::Trace, log);
  std::unique_ptr<GpuSampling> gpu;
  if (choice.backend == gpu::Backend::Cpu) {
    report.backend = "cpu";
    report.device = hostThreadsText();
    return gpu;
  }
  Stopwatch setup;
  gpu = std::make_unique<GpuSampling>(request, choice);
  report.backend = gpu::backendName(choice.backend);
  report.device = gpu->ctx.deviceName();
  report.deviceSeconds += setup.seconds();
  return gpu;
}

void addLoadTimes(const LoadedSnapshot& s, PathlineReport& report) {
  report.readSeconds += s.readSeconds;
  report.buildSeconds += s.buildSeconds;
  report.cellsRead += s.cellCount;
}

// Traces the particles through the intervals of snapshots first..last, loading each next
// snapshot on another thread while the current interval is traced.
void traceIntervals(const PathlineJob& job, std::size_t first, std::size_t last,
                    std::unique_ptr<LoadedSnapshot> a, std::unique_ptr<GpuSampling>& gpu,
                    flow::PathlineTracer& tracer, PathlineReport& report,
                    const Reporter& reporter) {
  const std::span<const SnapshotFile> series = job.series;
  const auto loadAhead = [&](std::size_t i) {
    return std::async(std::launch::async, [&, i] { return loadSnapshot(series[i], job, false); });
  };
  std::future<std::unique_ptr<LoadedSnapshot>> next = loadAhead(first + 1);
  std::unique_ptr<gpu::VectorProbe> probeA, probeB;
  if (gpu) probeA = gpu->probe(volumeOf(*a->field), report);
  for (std::size_t i = first; i < last; ++i) {
    Stopwatch waiting;
    std::unique_ptr<LoadedSnapshot> b = next.get();
    report.waitSeconds += waiting.seconds();
    addLoadTimes(*b, report);
    checkLikeTheFirst(*b, series[i + 1].path, report);
    if (i + 2 <= last) next = loadAhead(i + 2);
    if (gpu) probeB = gpu->probe(volumeOf(*b->field), report);
    Stopwatch tracing;
    if (gpu) gpu->stepper.bind(*probeA, *probeB);
    tracer.advance({a->time, &volumeOf(*a->field), samplerOf(probeA.get())},
                   {b->time, &volumeOf(*b->field), samplerOf(probeB.get())},
                   gpu ? &gpu->stepper : nullptr);
    report.traceSeconds += tracing.seconds();
    if (probeA) addProbeTimes(*probeA, report);
    probeA = std::move(probeB);
    a = std::move(b);
    reporter.advance("intervals", i - first + 1, last - first);
  }
  if (probeA) addProbeTimes(*probeA, report);
  if (gpu) {
    const gpu::PathlineStepper::Times& t = gpu->stepper.times();
    report.stepRounds = t.rounds;
    report.stepDispatches = t.dispatches;
    report.stepDeviceSeconds = t.deviceSeconds;
    report.stepCollectSeconds = t.collectSeconds;
  }
}

void sayPathlineSummary(const flow::PathlineTracer& tracer, const PathlineReport& report,
                        const Log& log) {
  say(log, fmt::format("stepping   dt = {:g} from t = {:g} to {:g}{}, {} snapshots used, "
                       "interpolant {}",
                       report.stepSize, report.startTime, report.endTime,
                       report.releaseEvery > 0.0
                           ? fmt::format(", released every {:g}", report.releaseEvery)
                           : std::string(),
                       report.snapshotsUsed, report.interpolant));
  say(log, fmt::format("particles  {} ({} seeds), {} steps; reasons {}",
                       withCommas(tracer.particleCount()), withCommas(report.seedCount),
                       withCommas(report.steps), reasonHistogram(tracer.reasons())));
  const double readBuild = report.readSeconds + report.buildSeconds;
  say(log, fmt::format("time       {:.2f} s in all: reading {:.2f} s and building {:.2f} s ({} "
                       "cells), device setup {:.2f} s, tracing {:.2f} s ({:.3g} "
                       "particle-steps/s), waiting for snapshots {:.2f} s; {:.2f}x the reading "
                       "and building",
                       report.wallSeconds, report.readSeconds, report.buildSeconds,
                       withCommas(report.cellsRead), report.deviceSeconds, report.traceSeconds,
                       double(report.steps) / std::max(report.traceSeconds, 1e-9),
                       report.waitSeconds, report.wallSeconds / std::max(readBuild, 1e-9)));
  if (report.stepRounds > 0)
    say(log, fmt::format(
                 "steps      {} dispatches in {} rounds on the device: the device {:.2f} "
                 "s, storing the points {:.2f} s; releases' samples {} batches, {:.2f} s",
                 withCommas(report.stepDispatches), withCommas(report.stepRounds),
                 report.stepDeviceSeconds, report.stepCollectSeconds, withCommas(report.probeCalls),
                 report.probeWriteSeconds + report.probeDeviceSeconds + report.probeReadSeconds));
}

std::vector<output::FieldDataArray> pathlineProvenance(std::span<const SnapshotFile> series,
                                                       const PathlineReport& report,
                                                       const std::string& kind) {
  using output::numberField;
  using output::textField;
  const DatasetInfo& info = report.firstInfo;
  std::vector<output::FieldDataArray> fields{
      textField("amrstream", "amrstream " AMRSTREAM_VERSION),
      textField("Output", kind),
      textField("Input", fmt::format("{} snapshots, {} ... {}", series.size(), series.front().path,
                                     series.back().path)),
      textField("InputFormat", info.format),
      textField("Vector", report.vectorName),
      textField("PointDataChannels", joined(report.channelNames)),
      textField("Seeds", fmt::format("{} from {}", report.seedCount, report.seedDescription)),
      textField("Interpolant", report.interpolant),
      textField("StepMode", "time"),
      numberField("StepSize", report.stepSize),
      numberField("StartTime", report.startTime),
      numberField("EndTime", report.endTime),
      numberField("ReleaseEvery", report.releaseEvery),
      textField("Backend", report.backend + " on " + report.device),
  };
  if (!info.timeUnit.empty()) fields.push_back(textField("TimeUnit", info.timeUnit));
  if (!info.lengthUnit.empty()) fields.push_back(textField("LengthUnit", info.lengthUnit));
  return fields;
}

}  // namespace

PathlineResult tracePathlines(const PathlineJob& job, const Reporter& reporter) {
  const Log& log = reporter.log;
  const std::span<const SnapshotFile> series = job.series;
  // v - U at fixed points is not the flow seen from a frame moving at U when v changes in time:
  // that is v(x + U t, t) - U.
  if (!job.field.frameVelocity.empty())
    throw settingError("frame_velocity",
                       "is for streamlines of one snapshot: a particle's path is the same in any "
                       "frame (a point at time t moves by -U t in a frame moving at U)");
  if (series.size() < 2)
    throw InputError("pathlines",
                     fmt::format("a series needs two snapshots or more; {} given", series.size()));
  say(log, fmt::format("series     {} snapshots from t = {:g} ({}) to {:g} ({})", series.size(),
                       series.front().time, series.front().path, series.back().time,
                       series.back().path));
  Stopwatch wall;
  PathlineResult result;
  PathlineReport& report = result.report;
  std::unique_ptr<GpuSampling> gpu = openSampling(job.backend, report, log);
  reporter.lap("device");
  const flow::PathlineOptions options = pathlineOptions(series, job.settings);
  report.stepSize = options.stepSize;
  report.startTime = options.startTime;
  report.endTime = options.endTime;
  report.releaseEvery = options.releaseEvery;
  const auto [first, last] = snapshotsUsed(series, options.startTime, options.endTime);
  report.snapshotsUsed = last - first + 1;

  // On the heap: a GPU probe points at its snapshot's volume, which must not move.
  std::unique_ptr<LoadedSnapshot> a = loadSnapshot(series[first], job, true);
  addLoadTimes(*a, report);
  const flow::VectorVolume& firstVolume = volumeOf(*a->field);
  report.vectorName = firstVolume.vectorName;
  report.channelNames = firstVolume.channelNames;
  report.interpolant = interpolantName(firstVolume.interpolant);
  report.firstInfo = a->field->info();

  flow::SeedList seeds =
      chooseSeeds(job.seeds, domainOf(firstVolume), &cellsOf(*a->cells), report.seedDescription);
  placeSeeds(firstVolume, seeds);
  a->cells.reset();
  report.seedCount = seeds.points.size();
  say(log, fmt::format("seeds      {} from {}", seeds.points.size(), report.seedDescription));
  reporter.lap("first snapshot and seeds");
  checkReleases(options, seeds.points.size(), report.channelNames.size());
  flow::PathlineTracer tracer(seeds.points, options, report.vectorName, report.channelNames);
  say(log, fmt::format("tracing    backend {} on {}", report.backend, report.device));
  traceIntervals(job, first, last, std::move(a), gpu, tracer, report, reporter);
  tracer.finish();
  if (gpu) checkValidation(gpu->ctx);
  report.steps = tracer.stepCount();
  report.particleCount = tracer.particleCount();
  report.wallSeconds = wall.seconds();
  // The next snapshots are read and built while an interval is traced: the wait for them is
  // what reading costs the run.
  reporter.lap("intervals",
               {{"tracing", report.traceSeconds}, {"waiting for snapshots", report.waitSeconds}});
  sayPathlineSummary(tracer, report, log);

  result.streaklines = options.releaseEvery > 0.0;
  Traces::Impl lines;
  lines.lines = result.streaklines ? tracer.streaklines() : tracer.pathlines();
  lines.provenance =
      pathlineProvenance(series, report, result.streaklines ? "streaklines" : "pathlines");
  lines.report = {report.backend, report.device, report.deviceSeconds, report.traceSeconds};
  lines.stepMode = flow::StepMode::Time;
  result.lines = tracesOf(std::move(lines));
  return result;
}

void runPathlineJob(const PathlineJob& job, const TraceOutput& output, const Reporter& reporter) {
  const PathlineResult result = tracePathlines(job, reporter);
  const WrittenLines written = result.lines.write(output);
  reporter.lap("output");
  say(reporter.log,
      fmt::format("output     {} ({} {}, {} points) [{:.2f} s]", output.path,
                  withCommas(written.lines), result.streaklines ? "streaklines" : "pathlines",
                  withCommas(written.points), written.seconds));
  say(reporter.log, fmt::format("memory     {:.2f} GiB peak resident on the host",
                                double(peakResidentBytes()) / 0x1p30));
}

}  // namespace amrstream
