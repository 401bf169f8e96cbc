#include "pathlines_command.hpp"

#include <memory>

#include "amrstream/pathlines.hpp"
#include "amrstream/run_files.hpp"
#include "console.hpp"
#include "dataset_options.hpp"
#include "job_options.hpp"
#include "option_checks.hpp"
#include "setting_options.hpp"

namespace amrstream::cli {

namespace {

struct PathlinesOptions {
  std::vector<std::string> snapshots;
  PathlineJob job;
  TraceOutput out{"pathlines.vtp"};
};

void runPathlines(PathlinesOptions o) {
  checkSeedRequest(o.job.seeds);
  o.job.series = listSnapshots(o.snapshots);
  RunFiles files;
  for (const SnapshotFile& snapshot : o.job.series) files.addInputs(datasetFiles(snapshot.path));
  if (!o.job.seeds.file.empty()) files.addInput(o.job.seeds.file);
  files.addOutput("--out", o.out.path);
  requireOutputExtension("--out", o.out.path, {".vtp"}, "VTK XML PolyData");
  const Console console;
  runPathlineJob(o.job, o.out, console);
  console.sayStages();
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
  PathlineJob& job = options->job;
  addFieldOptions(*command, job.field);
  addUnitOptions(*command, job.units);
  // The seeds are chosen inside the run (on the snapshot at the start time): no --seeds-out.
  addSeedOptions(*command, job.seeds, nullptr);
  addSetting(*command, settings::kStartTime, job.settings.startTime);
  addSetting(*command, settings::kEndTime, job.settings.endTime);
  addSetting(*command, settings::kTimeStep, job.settings.stepSize);
  addSetting(*command, settings::kReleaseEvery, job.settings.releaseEvery);
  addBackendOptions(*command, job.backend);
  command->add_option("--out", options->out.path, "output .vtp file")->capture_default_str();
  addSetting(*command, settings::kCompression, options->out.compression);
  command->callback([options] {
    options->job.backend.validation = validationRequested();
    runPathlines(*options);
  });
}

}  // namespace amrstream::cli
