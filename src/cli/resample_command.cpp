#include "resample_command.hpp"

#include <memory>

#include "amrstream/resample.hpp"
#include "amrstream/run_files.hpp"
#include "console.hpp"
#include "dataset_options.hpp"
#include "job_options.hpp"
#include "option_checks.hpp"

namespace amrstream::cli {

namespace {

void runResample(const ResampleJob& job) {
  checkResampleJob(job);
  RunFiles files;
  files.addInputs(datasetFiles(job.dataset.input));
  files.addOutput("--out", job.out);
  requireOutputExtension("--out", job.out, {".vti"}, "VTK XML ImageData");
  const Console console;
  runResampleJob(job, console);
  console.sayStages();
}

}  // namespace

void addResampleCommand(CLI::App& app) {
  auto options = std::make_shared<ResampleJob>();
  CLI::App* command = app.add_subcommand(
      "resample", "the reconstructed vector and point data on a uniform grid, as VTK ImageData");
  addDatasetOptions(*command, options->dataset, "--gen-seed");
  addFieldOptions(*command, options->field);
  addFrameVelocityOption(*command, options->field);
  command
      ->add_option("--dims", options->dims,
                   "points per axis: N for the longest axis of the box (the others in "
                   "proportion), or NX,NY,NZ")
      ->delimiter(',')
      ->check(countIn(1, 65535))
      ->capture_default_str();
  command
      ->add_option("--box", options->box,
                   "the box the grid's cells fill: x0,y0,z0,x1,y1,z1 (default: the domain)")
      ->delimiter(',')
      ->expected(6)
      ->check(finiteFloat());
  command->add_option("--compression", options->compression, "compression of the .vti's arrays")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "zlib", "lz4"}));
  command->add_option("--out", options->out, "output .vti file")->capture_default_str();
  command->callback([options] { runResample(*options); });
}

}  // namespace amrstream::cli
