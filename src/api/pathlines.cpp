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
#include "api/pathline_setup.hpp"
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
    return std::async(std::launch::async,
                      [&, i] { return loadSnapshot(series[i], job.field, job.units, false); });
  };
  std::future<std::unique_ptr<LoadedSnapshot>> next = loadAhead(first + 1);
  std::unique_ptr<gpu::VectorProbe> probeA, probeB;
  if (gpu) probeA = gpu->probe(volumeOf(*a->field), report);
  for (std::size_t i = first; i < last; ++i) {
    Stopwatch waiting;
    std::unique_ptr<LoadedSnapshot> b = next.get();
    report.waitSeconds += waiting.seconds();
    addLoadTimes(*b, report);
    // a is like the first
    checkLikeTheFirst(volumeOf(*b->field), series[i + 1].path, volumeOf(*a->field));
    if (i + 2 <= last) next = loadAhead(i + 2);
    if (gpu) probeB = gpu->probe(volumeOf(*b->field), report);
    Stopwatch tracing;
    if (gpu) gpu->stepper.bind(*probeA, *probeB);
    tracer.advance({a->time, &volumeOf(*a->field), probeSampler(probeA.get())},
                   {b->time, &volumeOf(*b->field), probeSampler(probeB.get())},
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
      textField("PointDataChannels", joinedNames(report.channelNames)),
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
  std::unique_ptr<LoadedSnapshot> a = loadSnapshot(series[first], job.field, job.units, true);
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
  tracer.planStorage(snapshotTimes(series, first, last));
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
  lines.lines = result.streaklines ? tracer.streaklines() : std::move(tracer).takePathlines();
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
