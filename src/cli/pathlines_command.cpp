#include "pathlines_command.hpp"

#include <fmt/format.h>

#include <memory>

#include "amrstream/pathlines.hpp"
#include "amrstream/tracing.hpp"
#include "dataset_files.hpp"
#include "dataset_options.hpp"
#include "option_checks.hpp"
#include "output/vtp_writer.hpp"
#include "progress.hpp"
#include "trace_job.hpp"
#include "util/peak_memory.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct PathlinesOptions {
  std::vector<std::string> snapshots;
  FieldOptions field;
  SeedRequest seeds;
  std::optional<double> startTime, endTime, stepSize;
  double releaseEvery = 0.0;
  BackendRequest backend;
  std::string out = "pathlines.vtp";
  std::string compression = "zlib";
};

void runPathlines(const PathlinesOptions& o) {
  checkSeedRequest(o.seeds);
  const std::vector<SnapshotFile> series = listSnapshots(o.snapshots);
  RunFiles files;
  for (const SnapshotFile& snapshot : series) files.addInputs(datasetFiles(snapshot.path));
  if (!o.seeds.file.empty()) files.addInput(o.seeds.file);
  files.addOutput("--out", o.out);
  fmt::print("series     {} snapshots from t = {:g} ({}) to {:g} ({})\n", series.size(),
             series.front().time, series.front().path, series.back().time, series.back().path);
  PathlineSettings settings;
  settings.startTime = o.startTime;
  settings.endTime = o.endTime;
  settings.stepSize = o.stepSize;
  settings.releaseEvery = o.releaseEvery;

  PathlineReport report;
  const flow::PathlineTracer tracer = [&] {
    Progress progress("intervals", series.size() - 1);
    return tracePathlines(
        series, o.field, o.seeds, settings, o.backend, report,
        [&](std::size_t done, std::size_t) { progress.update(done); }, printLineAfter(progress));
  }();
  const flow::PathlineOptions& options = report.options;
  fmt::print("stepping   dt = {:g} from t = {:g} to {:g}{}, {} snapshots used, interpolant {}\n",
             options.stepSize, options.startTime, options.endTime,
             options.releaseEvery > 0.0 ? fmt::format(", released every {:g}", options.releaseEvery)
                                        : std::string(),
             report.snapshotsUsed, report.interpolant);

  const bool streaks = options.releaseEvery > 0.0;
  const flow::TraceSet lines = streaks ? tracer.streaklines() : tracer.pathlines();
  fmt::print("particles  {} ({} seeds), {} steps; reasons {}\n", withCommas(tracer.particleCount()),
             withCommas(report.seedCount), withCommas(report.steps),
             reasonHistogram(tracer.reasons()));
  const double readBuild = report.readSeconds + report.buildSeconds;
  fmt::print(
      "time       {:.2f} s in all: reading {:.2f} s and building {:.2f} s ({} cells), "
      "device setup {:.2f} s, tracing {:.2f} s ({:.3g} particle-steps/s), waiting for "
      "snapshots {:.2f} s; {:.2f}x the reading and building\n",
      report.wallSeconds, report.readSeconds, report.buildSeconds, withCommas(report.cellsRead),
      report.deviceSeconds, report.traceSeconds,
      double(report.steps) / std::max(report.traceSeconds, 1e-9), report.waitSeconds,
      report.wallSeconds / std::max(readBuild, 1e-9));

  if (report.probeCalls > 0)
    fmt::print(
        "samples    {} batches on the device: writing the points {:.2f} s, the device "
        "{:.2f} s, reading the samples {:.2f} s\n",
        withCommas(report.probeCalls), report.probeWriteSeconds, report.probeDeviceSeconds,
        report.probeReadSeconds);

  Stopwatch clock;
  output::VtpWriteOptions writeOptions;
  writeOptions.compression = *output::compressionNamed(o.compression);  // checked by CLI11
  writeOptions.fieldData =
      pathlineProvenance(series, report, streaks ? "streaklines" : "pathlines");
  const output::VtpCounts written = output::writeVtp(o.out, lines, writeOptions);
  fmt::print("output     {} ({} {}, {} points) [{:.2f} s]\n", o.out, withCommas(written.lines),
             streaks ? "streaklines" : "pathlines", withCommas(written.points), clock.seconds());
  fmt::print("memory     {:.2f} GiB peak resident on the host\n",
             double(peakResidentBytes()) / 0x1p30);
}

}  // namespace

void addPathlinesCommand(CLI::App& app) {
  auto options = std::make_shared<PathlinesOptions>();
  CLI::App* command = app.add_subcommand(
      "pathlines", "trace pathlines (or streaklines) through a time series of snapshots");
  command
      ->add_option("snapshots", options->snapshots,
                   "the snapshots: files, folders (AMReX plotfiles) or glob patterns such as "
                   "'run/ring-*.txt', in any order (sorted by the times the files state)")
      ->required();
  addFieldOptions(*command, options->field);
  // The seeds are chosen inside the run (on the snapshot at the start time): no --seeds-out.
  addSeedOptions(*command, options->seeds, nullptr);
  command
      ->add_option("--start-time", options->startTime,
                   "release the particles at this time (default: the first snapshot's)")
      ->check(finiteDouble());
  command
      ->add_option("--end-time", options->endTime,
                   "stop the particles at this time (default: the last snapshot's)")
      ->check(finiteDouble());
  command
      ->add_option("--step-size", options->stepSize,
                   "RK4 time step (default: a tenth of the shortest interval between the "
                   "snapshots used); steps end on every snapshot's time")
      ->check(positiveDouble());
  command
      ->add_option("--release-every", options->releaseEvery,
                   "release new particles from the seeds at this interval and write streaklines "
                   "(one line per seed through its particles at the end time)")
      ->check(positiveDouble());
  command
      ->add_option("--backend", options->backend.backend,
                   "auto (as for trace), rayquery, pipeline, compute or cpu: where the RK4 "
                   "stages' samples are taken")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "rayquery", "pipeline", "compute", "cpu"}));
  command->add_option("--device", options->backend.device,
                      "the Vulkan device whose name contains this (see `amrstream devices`)");
  command->add_option("--out", options->out, "output .vtp file")->capture_default_str();
  command
      ->add_option("--compression", options->compression,
                   "compression of the .vtp's arrays: zlib, lz4 or none")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "zlib", "lz4"}));
  command->callback([options] {
    options->backend.validation = validationRequested();
    runPathlines(*options);
  });
}

}  // namespace amrstream::cli
