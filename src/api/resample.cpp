#include "amrstream/resample.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "amrstream/error.hpp"
#include "api/field_plan.hpp"
#include "api/frame_choice.hpp"
#include "api/handles.hpp"
#include "api/job_state.hpp"
#include "api/provenance.hpp"
#include "flow/uniform_resample.hpp"
#include "output/vti_writer.hpp"
#include "output/vtk_compression.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

namespace {

std::string channelList(const flow::VectorVolume& volume) {
  std::string names;
  for (const std::string& name : volume.channelNames) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none" : names;
}

// Loads the dataset and builds the field; the cells go once the field holds what sampling reads.
Field loadField(const ResampleJob& job, const Reporter& reporter) {
  const Log& log = reporter.log;
  Stopwatch clock;
  const Dataset cells = load(job.dataset.input, job.dataset.builtin, job.dataset.units);
  say(log, fmt::format("input      {}: {} cells [{:.2f} s]", cells.source(),
                       withCommas(cells.cellCount()), clock.seconds()));
  const auto [cellChecks, overlapCheck] = cells.checkSeconds();
  reporter.lap("input", {{"cell checks", cellChecks}, {"overlap check", overlapCheck}});
  clock.restart();
  Field field = buildField(cells, job.field, KeepDataset::No);
  const flow::VectorVolume& volume = volumeOf(field);
  say(log,
      fmt::format("structure  {} bricks, {} regions, vector {}{}, point data {}, interpolant "
                  "{} [{:.2f} s]",
                  withCommas(volume.originalBrickCount), withCommas(volume.regions.regions.size()),
                  volume.vectorName, relativeToFrame(volume), channelList(volume),
                  interpolantName(volume.interpolant), clock.seconds()));
  reporter.lap("structure");
  return field;
}

}  // namespace

void checkResampleJob(const ResampleJob& job) {
  if (job.dataset.input.starts_with("builtin:")) checkBuiltinSize(job.dataset.builtin);
  flow::checkGridCounts(job.dims);
}

void runResampleJob(const ResampleJob& job, const Reporter& reporter) {
  const Log& log = reporter.log;
  const std::optional<output::Compression> compression = output::compressionNamed(job.compression);
  if (!compression)
    throw settingError("compression",
                       fmt::format("'{}' is not zlib, lz4 or none", job.compression));
  const Field field = loadField(job, reporter);
  const flow::VectorVolume& volume = volumeOf(field);
  const flow::UniformGridSpec spec = flow::uniformGridSpec(volume, job.dims, job.box);
  Stopwatch clock;
  const std::size_t rows = std::size_t(spec.dims[1]) * spec.dims[2];
  const flow::UniformGrid grid = flow::resampleUniform(
      volume, spec, [&](std::size_t done) { reporter.advance("resampling", done, rows); });
  const double seconds = clock.seconds();
  reporter.lap("resampling");
  const glm::dvec3 spacing = spec.spacing();
  say(log, fmt::format("grid       {} x {} x {} points, spacing {:g} x {:g} x {:g}, {} valid "
                       "({:.1f} %) [{:.2f} s, {:.3g} samples/s]",
                       spec.dims[0], spec.dims[1], spec.dims[2], spacing.x, spacing.y, spacing.z,
                       withCommas(grid.validCount),
                       100.0 * double(grid.validCount) / double(spec.pointCount()), seconds,
                       double(spec.pointCount()) / std::max(seconds, 1e-9)));
  clock.restart();
  output::VtiWriteOptions writeOptions;
  writeOptions.compression = *compression;
  writeOptions.vectorName = volume.vectorName;
  writeOptions.channelNames = volume.channelNames;
  writeOptions.fieldData = datasetProvenance(field.source(), field.info(), volume);
  output::writeVti(job.out, grid, writeOptions);
  reporter.lap("output");
  say(log, fmt::format("output     {} [{:.2f} s]", job.out, clock.seconds()));
}

}  // namespace amrstream
