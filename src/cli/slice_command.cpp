#include "slice_command.hpp"

#include <memory>

#include "amrstream/rendering.hpp"
#include "amrstream/run_files.hpp"
#include "amrstream/slice.hpp"
#include "console.hpp"
#include "dataset_options.hpp"
#include "job_options.hpp"
#include "option_checks.hpp"

namespace amrstream::cli {

namespace {

// CLI11 fills fixed-size arrays element by element; the job holds them as optionals.
struct SliceOptions {
  SliceJob job;
  std::vector<double> point, window, range;
  bool noLines = false;
};

void runSlice(SliceOptions& options) {
  SliceJob& job = options.job;
  if (!options.point.empty())
    job.slice.point = std::array<double, 3>{options.point[0], options.point[1], options.point[2]};
  if (!options.window.empty())
    job.slice.window = std::array<double, 4>{options.window[0], options.window[1],
                                             options.window[2], options.window[3]};
  if (!options.range.empty())
    job.slice.range = std::array<double, 2>{options.range[0], options.range[1]};
  job.slice.lines = !options.noLines;
  job.slice.backend.validation = validationRequested();
  checkSliceJob(job);
  RunFiles files;
  files.addInputs(datasetFiles(job.dataset.input));
  files.addOutput("--out", job.out);
  requireOutputExtension("--out", job.out, {".png"}, "PNG");
  if (!job.vti.empty()) {
    files.addOutput("--vti", job.vti);
    requireOutputExtension("--vti", job.vti, {".vti"}, "VTK XML ImageData");
  }
  if (!job.vtp.empty()) {
    files.addOutput("--vtp", job.vtp);
    requireOutputExtension("--vtp", job.vtp, {".vtp"}, "VTK XML PolyData");
  }
  const Console console;
  runSliceJob(job, console);
  console.sayStages();
}

}  // namespace

void addSliceCommand(CLI::App& app) {
  auto options = std::make_shared<SliceOptions>();
  SliceJob& job = options->job;
  CLI::App* command = app.add_subcommand(
      "slice",
      "a plane through the data: a channel on it, the field lines of the vector's part "
      "in it and a LIC texture, as a PNG figure");
  addDatasetOptions(*command, job.dataset, "--gen-seed");
  addFieldOptions(*command, job.field);
  addFrameVelocityOption(*command, job.field);
  command
      ->add_option("--normal", job.slice.normal,
                   "the plane's normal: x, y, z (the figure's axes are then (y, z), (z, x), "
                   "(x, y), as yt's), or NX,NY,NZ")
      ->capture_default_str();
  command
      ->add_option("--point", options->point,
                   "x,y,z: a point the plane passes through (default: the domain's centre)")
      ->delimiter(',')
      ->expected(3)
      ->check(finiteFloat());
  command
      ->add_option("--window", options->window,
                   "a0,b0,a1,b1: the part of the plane shown, in its coordinates (the axes' "
                   "values; default: the domain)")
      ->delimiter(',')
      ->expected(4)
      ->check(finiteFloat());
  command->add_option("--width", job.slice.width, "pixels across the window (up in proportion)")
      ->check(countIn(1, 16384))
      ->capture_default_str();
  command
      ->add_option("--background", job.slice.background,
                   "a channel shown in colours, magnitude (the vector's), none, or auto (a "
                   "density channel where there is one, else the magnitude)")
      ->capture_default_str();
  command->add_option("--colour-map", job.slice.colourMap, colourMapNames())->capture_default_str();
  command->add_option("--colour-scale", job.slice.colourScale, "linear, log or symlog")
      ->check(CLI::IsMember({"linear", "log", "symlog"}))
      ->capture_default_str();
  command
      ->add_option("--range", options->range,
                   "MIN,MAX of the background's colours (default: its range on the plane)")
      ->delimiter(',')
      ->expected(2)
      ->check(finiteFloat());
  command->add_flag("--no-lines", options->noLines, "leave out the field lines");
  command
      ->add_option("--line-separation", job.slice.lineSeparation,
                   "the distance between neighbouring field lines, in the plane's "
                   "coordinates (0: 1/30 of the window's width)")
      ->check(finiteFloat())
      ->capture_default_str();
  command
      ->add_option("--line-width", job.slice.lineWidth,
                   "the field lines' width in pixels (with --line-width-by, the widest)")
      ->check(finiteFloat())
      ->capture_default_str();
  command->add_option("--line-colour-by", job.slice.lineColourBy,
                      "colour the field lines by a channel along them, or magnitude (the "
                      "vector's length), with a colour bar of their own");
  command->add_option("--line-colour-map", job.slice.lineColourMap, colourMapNames())
      ->capture_default_str();
  command->add_option("--line-colour-scale", job.slice.lineColourScale, "linear, log or symlog")
      ->check(CLI::IsMember({"linear", "log", "symlog"}))
      ->capture_default_str();
  command->add_option("--line-width-by", job.slice.lineWidthBy,
                      "make the field lines wider where a channel (or magnitude) is larger: "
                      "from a fifth of --line-width at its least to --line-width at its most");
  command->add_flag("--lic", job.slice.lic,
                    "shade the figure with a line integral convolution of the in-plane vector "
                    "(grey, with --background none)");
  command
      ->add_option("--lic-length", job.slice.licLength,
                   "how far the LIC kernel reaches along the field each way, in the plane's "
                   "coordinates (0: 1/50 of the window's width)")
      ->check(finiteFloat())
      ->capture_default_str();
  addBackendOptions(*command, job.slice.backend);
  command->add_option("--out", job.out, "output PNG figure")->capture_default_str();
  command->add_option("--vti", job.vti,
                      "also write the plane's samples (the vector, the point data and LIC) as "
                      "VTK ImageData");
  command->add_option("--vtp", job.vtp,
                      "also write the field lines as VTK PolyData, on the plane, with the "
                      "vector, the point data and ArcLength along them");
  command->callback([options] { runSlice(*options); });
}

}  // namespace amrstream::cli
