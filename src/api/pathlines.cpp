#include "amrstream/pathlines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <future>
#include <memory>
#include <set>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "amrstream/dataset.hpp"
#include "formats/snapshot_time.hpp"
#include "gpu/vector_probe.hpp"
#include "util/host_memory.hpp"
#include "util/host_threads.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

namespace {

struct LoadedSnapshot {
  double time = 0.0;
  Field field;
  std::optional<Dataset> cells;  // kept for the first only: density seeding reads them
  std::uint64_t cellCount = 0;
  double readSeconds = 0.0, buildSeconds = 0.0;
};

std::unique_ptr<LoadedSnapshot> loadSnapshot(const SnapshotFile& file, const FieldOptions& options,
                                             bool keepCells) {
  auto owned = std::make_unique<LoadedSnapshot>();
  LoadedSnapshot& loaded = *owned;
  loaded.time = file.time;
  Stopwatch clock;
  Dataset cells = load(file.path);
  loaded.readSeconds = clock.seconds();
  loaded.cellCount = cells.cellCount();
  clock.restart();
  loaded.field = buildField(cells, options);
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
  const flow::VectorVolume& v = s.field.volume;
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

  GpuSampling(const BackendRequest& request, const BackendChoice& choice)
      : ctx(createContext(request, choice)),
        kernel(gpu::createTraceKernel(ctx, choice.backend, gpu::KernelProgram::LocateProbe)) {}

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

flow::PathlineTracer tracePathlines(std::span<const SnapshotFile> series, const FieldOptions& field,
                                    const SeedRequest& seedRequest,
                                    const PathlineSettings& settings,
                                    const BackendRequest& backendRequest, PathlineReport& report,
                                    const IntervalProgress& progress, const Log& log) {
  Stopwatch wall;
  const BackendChoice choice = chooseBackend(backendRequest, BackendUse::Trace, log);
  std::optional<GpuSampling> gpu;
  if (choice.backend == gpu::Backend::Cpu) {
    report.backend = "cpu";
    report.device = hostThreadsText();
  } else {
    Stopwatch setup;
    gpu.emplace(backendRequest, choice);
    report.backend = gpu::backendName(choice.backend);
    report.device = gpu->ctx.deviceName();
    report.deviceSeconds += setup.seconds();
  }
  const double seriesStart = series.front().time, seriesEnd = series.back().time;
  flow::PathlineOptions& options = report.options;
  options.startTime = settings.startTime.value_or(seriesStart);
  options.endTime = settings.endTime.value_or(seriesEnd);
  if (options.startTime < seriesStart || options.startTime >= seriesEnd)
    throw InputError("--start-time",
                     fmt::format("{:g} is outside the series, which runs from {:g} to {:g}",
                                 options.startTime, seriesStart, seriesEnd));
  if (!(options.endTime > options.startTime))
    throw InputError("--end-time", fmt::format("{:g} is not after the start time {:g}",
                                               options.endTime, options.startTime));
  if (options.endTime >= seriesEnd) {
    options.endTime = seriesEnd;
    options.endReason = AMRSTREAM_REASON_SERIES_END;
  }
  const auto [first, last] = snapshotsUsed(series, options.startTime, options.endTime);
  double shortest = seriesEnd - seriesStart;
  for (std::size_t i = first; i < last; ++i)
    shortest = std::min(shortest, series[i + 1].time - series[i].time);
  options.stepSize = settings.stepSize.value_or(shortest / 10);
  if (!(options.stepSize > 0.0) || !std::isfinite(options.stepSize))
    throw InputError("--step-size", fmt::format("{:g} is not a positive time", options.stepSize));
  if (settings.releaseEvery < 0.0 || !std::isfinite(settings.releaseEvery))
    throw InputError("--release-every",
                     fmt::format("{:g} is not a positive time", settings.releaseEvery));
  options.releaseEvery = settings.releaseEvery;
  options.maxResultBytes =
      settings.maxResultBytes > 0
          ? settings.maxResultBytes
          : static_cast<std::uint64_t>(kTraceMemoryShare * physicalMemoryBytes());
  report.snapshotsUsed = last - first + 1;

  // On the heap: a GPU probe points at its snapshot's volume, which must not move.
  std::unique_ptr<LoadedSnapshot> a = loadSnapshot(series[first], field, true);
  report.readSeconds += a->readSeconds;
  report.buildSeconds += a->buildSeconds;
  report.cellsRead += a->cellCount;
  const flow::VectorVolume& firstVolume = a->field.volume;
  report.vectorName = firstVolume.vectorName;
  report.channelNames = firstVolume.channelNames;
  report.interpolant = interpolantName(firstVolume.interpolant);
  report.firstInfo = a->field.info;
  const auto loadAhead = [&](std::size_t i) {
    return std::async(std::launch::async, [&, i] { return loadSnapshot(series[i], field, false); });
  };
  std::future<std::unique_ptr<LoadedSnapshot>> next = loadAhead(first + 1);

  flow::SeedList seeds =
      chooseSeeds(seedRequest, domainOf(firstVolume), &*a->cells, report.seedDescription);
  placeSeeds(firstVolume, seeds);
  a->cells.reset();
  report.seedCount = seeds.points.size();
  say(log, fmt::format("seeds      {} from {}", seeds.points.size(), report.seedDescription));
  flow::PathlineTracer tracer(seeds.points, options, report.vectorName, report.channelNames);
  say(log, fmt::format("tracing    backend {} on {}", report.backend, report.device));

  std::unique_ptr<gpu::VectorProbe> probeA, probeB;
  if (gpu) probeA = gpu->probe(a->field.volume, report);
  for (std::size_t i = first; i < last; ++i) {
    Stopwatch waiting;
    std::unique_ptr<LoadedSnapshot> b = next.get();
    report.waitSeconds += waiting.seconds();
    report.readSeconds += b->readSeconds;
    report.buildSeconds += b->buildSeconds;
    report.cellsRead += b->cellCount;
    checkLikeTheFirst(*b, series[i + 1].path, report);
    if (i + 2 <= last) next = loadAhead(i + 2);
    if (gpu) probeB = gpu->probe(b->field.volume, report);
    Stopwatch tracing;
    tracer.advance({a->time, &a->field.volume, samplerOf(probeA.get())},
                   {b->time, &b->field.volume, samplerOf(probeB.get())});
    report.traceSeconds += tracing.seconds();
    if (probeA) addProbeTimes(*probeA, report);
    probeA = std::move(probeB);
    a = std::move(b);
    if (progress) progress(i - first + 1, last - first);
  }
  if (probeA) addProbeTimes(*probeA, report);
  tracer.finish();
  if (gpu) checkValidation(gpu->ctx);
  report.steps = tracer.stepCount();
  report.wallSeconds = wall.seconds();
  return tracer;
}

std::vector<output::FieldDataArray> pathlineProvenance(std::span<const SnapshotFile> series,
                                                       const PathlineReport& report,
                                                       const std::string& kind) {
  using output::numberField;
  using output::textField;
  const flow::PathlineOptions& o = report.options;
  const bricks::DatasetInfo& info = report.firstInfo;
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
      numberField("StepSize", o.stepSize),
      numberField("StartTime", o.startTime),
      numberField("EndTime", o.endTime),
      numberField("ReleaseEvery", o.releaseEvery),
      textField("Backend", report.backend + " on " + report.device),
  };
  if (!info.timeUnit.empty()) fields.push_back(textField("TimeUnit", info.timeUnit));
  if (!info.lengthUnit.empty()) fields.push_back(textField("LengthUnit", info.lengthUnit));
  return fields;
}

}  // namespace amrstream
