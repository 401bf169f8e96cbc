#include "resample_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "amrstream/dataset.hpp"
#include "amrstream/field.hpp"
#include "amrstream/provenance.hpp"
#include "dataset_files.hpp"
#include "dataset_options.hpp"
#include "flow/uniform_resample.hpp"
#include "option_checks.hpp"
#include "output/vti_writer.hpp"
#include "output_paths.hpp"
#include "progress.hpp"
#include "trace_job.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct ResampleOptions {
  DatasetOptions dataset;
  FieldOptions field;
  std::vector<std::uint64_t> dims{128};
  std::vector<double> box;
  std::string compression = "zlib";
  std::string out = "resample.vti";
};

std::string channelList(const flow::VectorVolume& volume) {
  std::string names;
  for (const std::string& name : volume.channelNames) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none" : names;
}

void runResample(const ResampleOptions& o) {
  checkBuiltinSize(o.dataset);
  flow::checkGridCounts(o.dims);
  RunFiles files;
  files.addInputs(datasetFiles(o.dataset.input));
  files.addOutput("--out", o.out);

  Stopwatch clock;
  Field field = [&] {
    const Dataset cells = load(o.dataset.input, o.dataset.generator);
    fmt::print("input      {}: {} cells [{:.2f} s]\n", cells.source(),
               withCommas(cells.cellCount()), clock.seconds());
    clock.restart();
    return buildField(cells, o.field);
  }();  // the cells go here: the volume holds what sampling reads
  const flow::VectorVolume& volume = field.volume;
  fmt::print(
      "structure  {} bricks, {} regions, vector {}, point data {}, interpolant {} "
      "[{:.2f} s]\n",
      withCommas(volume.originalBrickCount), withCommas(volume.regions.regions.size()),
      volume.vectorName, channelList(volume), interpolantName(volume.interpolant), clock.seconds());

  const flow::UniformGridSpec spec = flow::uniformGridSpec(volume, o.dims, o.box);
  clock.restart();
  flow::UniformGrid grid;
  {
    Progress progress("resampling", std::size_t(spec.dims[1]) * spec.dims[2]);
    grid = flow::resampleUniform(volume, spec, [&](std::size_t rows) { progress.update(rows); });
  }
  const double seconds = clock.seconds();
  const glm::dvec3 spacing = spec.spacing();
  fmt::print(
      "grid       {} x {} x {} points, spacing {:g} x {:g} x {:g}, {} valid ({:.1f} %) "
      "[{:.2f} s, {:.3g} samples/s]\n",
      spec.dims[0], spec.dims[1], spec.dims[2], spacing.x, spacing.y, spacing.z,
      withCommas(grid.validCount), 100.0 * double(grid.validCount) / double(spec.pointCount()),
      seconds, double(spec.pointCount()) / std::max(seconds, 1e-9));

  clock.restart();
  output::VtiWriteOptions writeOptions;
  writeOptions.compression = *output::compressionNamed(o.compression);  // checked by CLI11
  writeOptions.vectorName = volume.vectorName;
  writeOptions.channelNames = volume.channelNames;
  writeOptions.fieldData = datasetProvenance(field.source, field.info, volume);
  output::writeVti(o.out, grid, writeOptions);
  fmt::print("output     {} [{:.2f} s]\n", o.out, clock.seconds());
}

}  // namespace

void addResampleCommand(CLI::App& app) {
  auto options = std::make_shared<ResampleOptions>();
  CLI::App* command = app.add_subcommand(
      "resample", "the reconstructed vector and point data on a uniform grid, as VTK ImageData");
  addDatasetOptions(*command, options->dataset, "--gen-seed");
  addFieldOptions(*command, options->field);
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
