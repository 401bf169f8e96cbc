#include "amrstream/trace_job.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "amrstream/error.hpp"
#include "api/declared_units.hpp"
#include "api/deferred_dataset.hpp"
#include "api/field_plan.hpp"
#include "api/frame_choice.hpp"
#include "api/input_share.hpp"
#include "api/job_state.hpp"
#include "api/provenance.hpp"
#include "api/seed_choice.hpp"
#include "api/stepping.hpp"
#include "api/traces_impl.hpp"
#include "formats/dataset_files.hpp"
#include "formats/load_input.hpp"
#include "output/seed_file_writer.hpp"
#include "output/vtk_compression.hpp"
#include "output/vtp_writer.hpp"
#include "util/huge_pages.hpp"
#include "util/parallel_copy.hpp"
#include "util/peak_memory.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

std::string withCommas(std::uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
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

// Counts the lines and their steps into `report` and says them.
void sayTraceSummary(const flow::TraceSet& traces, TraceReport& report, const Log& log) {
  std::uint64_t steps = 0;
  for (const std::uint32_t lineSteps : traces.steps) steps += lineSteps;
  report.lines = traces.lineCount();
  report.steps = steps;
  say(log, fmt::format("steps      {} taken in {} lines, {:.1f} per line", withCommas(steps),
                       withCommas(traces.lineCount()),
                       double(steps) / double(std::max<std::size_t>(1, traces.lineCount()))));
  say(log, fmt::format("reasons    {}", reasonHistogram(traces.reasons)));
  say(log, fmt::format("time       {:.3f} s tracing, {:.3g} particle-steps/s{}",
                       report.traceSeconds, double(steps) / std::max(report.traceSeconds, 1e-9),
                       report.setupSeconds > 0.0
                           ? fmt::format(" (device setup {:.2f} s before it)", report.setupSeconds)
                           : std::string()));
}

std::string outputLine(const std::filesystem::path& path, const WrittenLines& written) {
  return fmt::format("output     {} ({} polylines, {} points) [{:.2f} s]", path.string(),
                     withCommas(written.lines), withCommas(written.points), written.seconds);
}

WrittenLines writeLines(const flow::TraceView& traces, const TraceOutput& output,
                        std::vector<output::FieldDataArray> provenance) {
  const std::optional<output::Compression> compression =
      output::compressionNamed(output.compression);
  if (!compression)
    throw settingError("compression",
                       fmt::format("'{}' is not zlib, lz4 or none", output.compression));
  if (output.periodicLines != "split" && output.periodicLines != "unwrapped")
    throw settingError("periodic_lines",
                       fmt::format("'{}' is not split or unwrapped", output.periodicLines));
  output::VtpWriteOptions options;
  options.periodicLines = output.periodicLines == "unwrapped" ? output::PeriodicLines::Unwrapped
                                                              : output::PeriodicLines::Split;
  options.compression = *compression;
  options.fieldData = std::move(provenance);
  Stopwatch clock;
  const output::VtpCounts counts = output::writeVtp(output.path, traces, options);
  return {counts.lines, counts.points, clock.seconds()};
}

std::vector<output::FieldDataArray> jobProvenance(const PreparedJob::Impl& job) {
  const Field& field = job.field;
  return provenanceFields({field.source(), field.info(),
                           fmt::format("{} from {}", job.seeds.points.size(), job.seedDescription),
                           job.options, job.report},
                          volumeOf(field));
}

RunFiles jobFiles(const TraceJob& job) {
  if (job.dataset.input.starts_with("builtin:")) checkBuiltinSize(job.dataset.builtin);
  checkSeedRequest(job.seeds);
  RunFiles files;
  files.addInputs(formats::datasetFiles(job.dataset.input));
  if (!job.seeds.file.empty()) files.addInput(job.seeds.file);
  if (!job.seedsOut.empty()) files.addOutput("{seeds_out}", job.seedsOut);
  return files;
}

void PreparedJob::Impl::releaseDataset() {
  field.impl().dataset.reset();
  std::vector<std::uint32_t>().swap(volume().cellIds);
}

PreparedJob::PreparedJob(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PreparedJob::PreparedJob(PreparedJob&&) noexcept = default;
PreparedJob& PreparedJob::operator=(PreparedJob&&) noexcept = default;
PreparedJob::~PreparedJob() = default;
const Field& PreparedJob::field() const { return impl_->field; }
std::span<const glm::dvec3> PreparedJob::seeds() const { return impl_->seeds.points; }
const std::string& PreparedJob::seedDescription() const { return impl_->seedDescription; }
std::string PreparedJob::stepMode() const { return stepModeName(impl_->options.stepMode); }

namespace {

// The cells as read, and what the field is built from.
struct ReadInput {
  DeferredDataset data;
  bool deferred = false;
  double seconds = 0.0;
};

// Deferred: the channels stay in their files until the volume's layout and the seeds are made
// and the cells freed, so one channel at a time is in memory beside the volume (.exa inputs).
ReadInput readInput(const TraceJob& job, bool deferred, InputShare* share) {
  Stopwatch clock;
  ReadInput read;
  read.deferred = deferred;
  if (deferred) {
    read.data = loadDeferred(job.dataset.input, job.dataset.builtin);
  } else {
    read.data.cells = std::make_shared<bricks::AmrField>(
        formats::loadInput(job.dataset.input, job.dataset.builtin, share ? &share->window : nullptr,
                           share ? &share->read : nullptr));
    read.data.catalog = flow::catalogOf(*read.data.cells);
  }
  read.seconds = clock.seconds();
  return read;
}

void sayInput(const bricks::AmrField& cells, const flow::VectorChannels& vector, double seconds,
              const Log& log) {
  say(log, fmt::format("input      {}: {} cells, levels {}..{}, vector {} = ({}, {}, {}){} "
                       "[{:.2f} s]",
                       cells.source(), withCommas(cells.cellCount()),
                       cells.info().fileLevel(cells.coarsestLevel()),
                       cells.info().fileLevel(cells.finestLevel()), vector.name, vector.channels[0],
                       vector.channels[1], vector.channels[2].empty() ? "0" : vector.channels[2],
                       timeAndUnitsClause(cells.info()), seconds));
}

void sayStructure(const flow::VectorVolume& volume, const FieldBuildTimes& times, const Log& log) {
  const std::size_t images = volume.bricks.size() - volume.originalBrickCount;
  say(log,
      fmt::format("structure  {} bricks{} [{:.2f} s], {} regions [{:.2f} s]{}",
                  withCommas(volume.originalBrickCount),
                  images > 0 ? fmt::format(" + {} periodic images ({})", withCommas(images),
                                           axesText(volume.periodic))
                             : std::string(),
                  times.bricks, withCommas(volume.regions.regions.size()), times.regions,
                  volume.interpolant == flow::Interpolant::Linear
                      ? fmt::format(", linear interpolant's gradients [{:.2f} s]", times.gradients)
                      : std::string()));
}

void sayPointData(const flow::VectorVolume& volume, bool vorticity, const Log& log) {
  std::string pointData;
  for (const std::string& name : volume.channelNames)
    pointData += (pointData.empty() ? "" : ", ") + name;
  if (vorticity) pointData += std::string(pointData.empty() ? "" : ", ") + "vorticity";
  say(log, "point data " + (pointData.empty() ? std::string("none") : pointData));
}

void sayStepping(const TraceSettings& settings, const flow::TraceOptions& options, const Log& log) {
  std::string limits;
  if (settings.maxLength > 0.0f) limits += fmt::format(", length <= {:g}", settings.maxLength);
  if (settings.maxTime > 0.0f) limits += fmt::format(", |time| <= {:g}", settings.maxTime);
  const std::string integrator =
      options.integrator == flow::Integrator::Rk45
          ? fmt::format("rk45 (tolerance {:g}, steps {:g} .. {:g})", options.tolerance,
                        options.minStep, options.maxStep)
          : integratorName(options.integrator);
  say(log,
      fmt::format("stepping   mode {}, h = {:g}, {}, {}, at most {} steps{}", settings.stepMode,
                  options.stepSize, integrator,
                  options.direction == flow::Direction::Both ? "both directions"
                                                             : directionName(options.direction),
                  settings.steps, limits));
}

// The seeds of a job whose field is built here, chosen between the cells' layout and the values
// (frame_velocity auto takes its mean over the region they were drawn from); not for a rank's
// share, whose ranks choose density seeds together once the values are read.
struct JobSeeds {
  bool here = false;
  flow::SeedList seeds;
  std::string description;
  std::string frameRegion;  // what auto's mean was taken over
};

// The seeds, those on the domain's upper faces moved inside (checked once the values are there).
// The density channel of a deferred input is read first, once the layout, whose build needs
// memory beside the cells, is made.
void chooseJobSeeds(const TraceJob& job, DeferredDataset& data, bool deferred,
                    const flow::VectorVolume& layout, JobSeeds& seeding) {
  const std::string& density = job.seeds.density;
  if (deferred && !density.empty() && !data.cells->findChannel(density)) {
    data.catalog.require(density);  // listing every channel when it is absent
    data.channels(density, [&](std::span<const float> values) {
      // A copy on all cores, its pages faulted in 2 MiB at a time.
      std::vector<float> copy;
      resizeInHugePages(copy, values.size());
      copyParallel(std::as_bytes(values), std::as_writable_bytes(std::span(copy)));
      data.cells->addChannel({density, std::move(copy)});
    });
  }
  seeding.seeds = chooseSeeds(job.seeds, domainOf(layout), data.cells.get(), seeding.description);
  flow::closeUpperFaces(layout, seeding.seeds);
}

// The field of `read`: the cells' layout (a share's, built from the same cells before their
// values were read, or built here), the seeds where they are chosen here, then the values, read
// from the cells or, deferred, from the channels' files once the cells are freed.
Field buildJobField(const TraceJob& job, ReadInput& read, FieldPlan& plan, InputShare* share,
                    JobSeeds& seeding, const Reporter& reporter) {
  DeferredDataset& data = read.data;
  const bricks::AmrField& cells = *data.cells;
  const std::string source = cells.source();
  const DatasetInfo info = cells.info();
  flow::VolumeBuildTimes times;
  flow::VectorVolume volume;
  if (share && share->layout) {
    volume = std::move(*share->layout);
    share->layout.reset();
    times = share->layoutTimes;
  } else {
    volume = flow::buildCellLayout(cells, plan.volume, &times);
  }
  reporter.lap("layout", {{"bricks", times.bricks}, {"regions", times.regions}});
  if (seeding.here) chooseJobSeeds(job, data, read.deferred, volume, seeding);
  reporter.lap("seeds");
  if (plan.frame.automatic) {
    // A share holds part of the values: its ranks read the whole input for auto's mean.
    if (share) throw std::logic_error("frame_velocity auto needs every rank to read the whole");
    plan.volume.autoFrame =
        seedingRegion(job.seeds, seeding.seeds.points, volume, seeding.frameRegion);
  }
  std::optional<Dataset> dataset;
  times.gather = times.gradients = 0.0;  // what fillVolumeValues sets is this stage's
  if (read.deferred) {
    data.cells.reset();  // the cells' corners and levels, and the channels loaded for the seeds
    reporter.lap("freeing");
    flow::fillVolumeValues(volume, plan.vector, plan.volume, source, data.channels, &times);
  } else {
    flow::fillVolumeValues(volume, cells, plan.vector, plan.volume, &times);
    dataset = datasetOf(std::move(*data.cells));
  }
  data.cells.reset();
  // Deferred, what is not gathering is reading the channels' values from their files.
  reporter.lap(read.deferred ? "values read" : "values",
               {{"gathers", times.gather}, {"gradients", times.gradients}});
  return fieldOf(std::move(volume), plan.vector, source, info, times, std::move(dataset));
}

PreparedJob prepareJob(const TraceJob& job, const PrepareOptions& options, InputShare* share,
                       const Reporter& reporter) {
  const Log& log = reporter.log;
  std::unique_ptr<DeviceOpening> opening;
  if (options.openDevice && options.seeds && !share && job.backend.backend != "cpu")
    opening = std::make_unique<DeviceOpening>(job.backend);
  const bool deferred = options.dataset == KeepDataset::No && options.seeds && !share;
  ReadInput read = readInput(job, deferred, share);
  FieldPlan plan = planField(read.data.catalog, read.data.cells->info(), job.field);
  std::vector<std::string> named = read.data.catalog.names;
  named.push_back(plan.vector.name);
  declareInputUnits(*read.data.cells, job.dataset.units, named);
  sayInput(*read.data.cells, plan.vector, read.seconds, log);
  const bricks::AmrField::CheckSeconds checks = read.data.cells->checkSeconds();
  reporter.lap("input", {{"cell checks", checks.cells}, {"overlap check", checks.overlaps}});

  JobSeeds seeding;
  seeding.here = options.seeds && !share;
  const std::uint64_t cellCount = read.data.cells->cellCount();
  auto prepared =
      std::make_unique<PreparedJob::Impl>(buildJobField(job, read, plan, share, seeding, reporter));
  PreparedJob::Impl& p = *prepared;
  p.cellCount = cellCount;
  p.backend = job.backend;
  p.opening = std::move(opening);
  p.seeds = std::move(seeding.seeds);
  p.seedDescription = std::move(seeding.description);
  const flow::VectorVolume& volume = p.volume();
  sayStructure(volume, p.field.buildTimes(), log);
  if (const std::optional<std::string> frame = frameLine(plan.frame, volume, seeding.frameRegion))
    say(log, *frame);
  if (!options.seeds) return PreparedJob(std::move(prepared));

  sayPointData(volume, job.trace.vorticity, log);
  if (share) {
    if (!job.seeds.density.empty()) {
      share->markOwned(p.cells(), share->owned);
      share->cells.owned = share->owned;
    }
    p.seeds =
        chooseSeeds(job.seeds, domainOf(volume), &p.cells(), p.seedDescription, &share->cells);
  }
  placeSeeds(volume, p.seeds);
  if (!job.seedsOut.empty()) output::writeSeedFile(job.seedsOut, p.seeds);

  p.options = traceOptions(job.trace, volume);
  say(log,
      fmt::format("seeds      {} from {}{}", withCommas(p.seeds.points.size()), p.seedDescription,
                  job.seedsOut.empty() ? "" : ", written to " + job.seedsOut));
  sayStepping(job.trace, p.options, log);
  reporter.lap("seeds");
  if (options.dataset == KeepDataset::No && !share) p.releaseDataset();
  reporter.lap("freeing");
  return PreparedJob(std::move(prepared));
}

}  // namespace

PreparedJob prepare(const TraceJob& job, const PrepareOptions& options, const Reporter& reporter) {
  return prepareJob(job, options, nullptr, reporter);
}

PreparedJob prepareShare(const TraceJob& job, InputShare& share, const Reporter& reporter) {
  return prepareJob(job, {true, KeepDataset::Yes}, &share, reporter);
}

PreparedJob prepare(const Field& field, std::vector<glm::dvec3> seeds,
                    const TraceSettings& settings, const BackendRequest& backend,
                    std::string seedDescription) {
  auto prepared = std::make_unique<PreparedJob::Impl>(field);
  PreparedJob::Impl& p = *prepared;
  p.backend = backend;
  p.seeds.points = std::move(seeds);
  p.seeds.origin = [](std::size_t i) { return fmt::format("seeds[{}]", i); };
  p.seedDescription = std::move(seedDescription);
  placeSeeds(p.volume(), p.seeds);
  p.options = traceOptions(settings, p.volume());
  return PreparedJob(std::move(prepared));
}

TracedLines::TracedLines(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
TracedLines::TracedLines(TracedLines&&) noexcept = default;
TracedLines& TracedLines::operator=(TracedLines&&) noexcept = default;
TracedLines::~TracedLines() = default;
const TraceReport& TracedLines::report() const { return impl_->report; }

WrittenLines TracedLines::write(const TraceOutput& output, const Log& log) const {
  const WrittenLines written = writeLines(impl_->held->view(), output, impl_->provenance);
  say(log, outputLine(output.path, written));
  return written;
}

Traces TracedLines::assemble() && {
  Traces::Impl traces;
  traces.lines = std::move(*impl_->held).assemble();
  traces.provenance = std::move(impl_->provenance);
  traces.report = impl_->report;
  traces.field = impl_->field;
  traces.stepMode = impl_->stepMode;
  impl_->held.reset();
  return tracesOf(std::move(traces));
}

TracedLines trace(PreparedJob& job, const TraceRunOptions& options, const Reporter& reporter) {
  PreparedJob::Impl& p = job.impl();
  const std::size_t seeds = p.seeds.points.size();
  // Progress counts seeds: lines finished, scaled by the lines per seed.
  const flow::TraceProgress progress = [&](std::size_t done, std::size_t lines) {
    reporter.advance("tracing", done * seeds / std::max<std::size_t>(1, lines), seeds);
  };
  auto traced = std::make_unique<TracedLines::Impl>(p.field);
  traced->held =
      traceForWriting(p.backend, p.volume(), p.seeds.points, p.options, options.store, progress,
                      &p.report, options.hostValues, reporter.log, p.opening.get());
  p.opening.reset();
  const TraceReport& r = p.report;
  reporter.lap("tracing",
               {{"backend choice", r.chooseSeconds},
                {"device", r.setupSeconds - r.uploadSeconds - r.structureSeconds - r.kernelSeconds},
                {"upload", r.uploadSeconds},
                {"structure", r.structureSeconds},
                {"kernels", r.kernelSeconds}});
  sayTraceSummary(traced->held->view().lines(), p.report, reporter.log);
  traced->provenance = jobProvenance(p);
  traced->report = p.report;
  traced->stepMode = p.options.stepMode;
  return TracedLines(std::move(traced));
}

std::string memoryLine(bool stagePeak, std::optional<std::uint64_t> tracingPeak) {
  const auto gib = [](std::uint64_t bytes) { return double(bytes) / 0x1p30; };
  std::string stages;
  if (stagePeak && tracingPeak)
    stages = fmt::format(", {:.2f} GiB while tracing, {:.2f} GiB while writing", gib(*tracingPeak),
                         gib(stagePeakResidentBytes()));
  else if (stagePeak)
    stages = fmt::format(", {:.2f} GiB while tracing and writing", gib(stagePeakResidentBytes()));
  return fmt::format("memory     {:.2f} GiB peak resident on the host{}", gib(peakResidentBytes()),
                     stages);
}

TraceJobSummary runTraceJob(const TraceJob& job, const TraceOutput& output, TraceStore store,
                            const Reporter& reporter) {
  TraceJobSummary summary;
  double tracesFreed = 0.0;
  {
    PreparedJob prepared = prepare(job, {true, KeepDataset::No, true}, reporter);
    const bool stagePeak = resetStagePeak();
    // Nothing after tracing reads the volume's values: a GPU backend may drop the host copy.
    TracedLines traced = trace(prepared, {store, HostValues::Release}, reporter);
    const std::uint64_t tracingPeak = stagePeakResidentBytes();
    resetStagePeak();
    const WrittenLines written = traced.write(output, reporter.log);
    reporter.lap("output");
    say(reporter.log, memoryLine(stagePeak, tracingPeak));
    const PreparedJob::Impl& p = prepared.impl();
    summary.input = p.field.source();
    summary.cells = p.cellCount;
    summary.seeds = p.seeds.points.size();
    summary.report = traced.report();
    summary.lines = summary.report.lines;
    summary.steps = summary.report.steps;
    summary.pointsWritten = written.points;
    // The traces go first, with the device when they are kept on it; then the volume.
    const Stopwatch freeing;
    { const TracedLines freed = std::move(traced); }
    tracesFreed = freeing.seconds();
  }
  reporter.lap("freeing", {{"freeing traces", tracesFreed}});
  if (reporter.clock) say(reporter.log, reporter.clock->line());
  return summary;
}

}  // namespace amrstream
