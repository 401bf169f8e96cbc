#include "api/pathline_setup.hpp"

#include <fmt/format.h>

#include <cmath>

#include "amrstream/error.hpp"
#include "amrstream/settings.hpp"
#include "api/field_plan.hpp"
#include "api/handles.hpp"
#include "gpu/vector_probe.hpp"
#include "util/host_memory.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

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

}  // namespace

std::unique_ptr<LoadedSnapshot> loadSnapshot(const SnapshotFile& file, const FieldOptions& field,
                                             const DeclaredUnits& units, bool keepCells) {
  auto owned = std::make_unique<LoadedSnapshot>();
  LoadedSnapshot& loaded = *owned;
  loaded.time = file.time;
  Stopwatch clock;
  Dataset cells = load(file.path, {}, units);
  loaded.readSeconds = clock.seconds();
  loaded.cellCount = cells.cellCount();
  clock.restart();
  loaded.field = buildField(cells, field, KeepDataset::No);
  loaded.buildSeconds = clock.seconds();
  if (keepCells) loaded.cells.emplace(std::move(cells));
  return owned;
}

std::string joinedNames(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ",") + name;
  return text.empty() ? "none" : text;
}

void checkLikeTheFirst(const flow::VectorVolume& v, const std::string& path,
                       const flow::VectorVolume& first) {
  if (v.vectorName != first.vectorName)
    throw InputError(path, fmt::format("its vector is '{}', the first snapshot's '{}'",
                                       v.vectorName, first.vectorName));
  if (v.channelNames != first.channelNames)
    throw InputError(path,
                     fmt::format("its point-data channels are {}, the first snapshot's {}",
                                 joinedNames(v.channelNames), joinedNames(first.channelNames)));
}

std::pair<std::size_t, std::size_t> snapshotsUsed(std::span<const SnapshotFile> series, double t0,
                                                  double t1) {
  std::size_t first = 0;
  while (first + 1 < series.size() && series[first + 1].time <= t0) ++first;
  std::size_t last = first + 1;
  while (last + 1 < series.size() && series[last].time < t1) ++last;
  return {first, last};
}

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

std::vector<double> snapshotTimes(std::span<const SnapshotFile> series, std::size_t first,
                                  std::size_t last) {
  std::vector<double> times;
  for (std::size_t i = first; i <= last; ++i) times.push_back(series[i].time);
  return times;
}

flow::VectorBatchSampler probeSampler(gpu::VectorProbe* probe) {
  if (!probe) return {};
  return [probe](std::span<const glm::vec3> cells, std::span<flow::VectorSample> out) {
    probe->sample(cells, out);
  };
}

}  // namespace amrstream
