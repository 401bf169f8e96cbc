#include "gen_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <limits>
#include <memory>
#include <vector>

#include "amrstream/builtin.hpp"
#include "amrstream/dataset.hpp"
#include "amrstream/dataset_writing.hpp"
#include "amrstream/error.hpp"
#include "amrstream/run_files.hpp"
#include "console.hpp"
#include "dataset_options.hpp"
#include "option_checks.hpp"
#include "option_limits.hpp"

namespace amrstream::cli {

namespace {

struct GenOptions {
  std::string kind;
  std::string out;
  BuiltinOptions generator;
  NestOptions nest;            // kind nest: its levels and time are the generator's
  std::vector<double> centre;  // kind nest: x,y,z; empty: NestOptions' default
  int series = 0;              // snapshots; 0: one dataset named by --out alone
  double interval = 0.1;       // time between snapshots
  std::string format = "exa";  // writableFormats()
};

bool isNest(const GenOptions& o) { return o.kind == "nest"; }

NestOptions nestOptions(const GenOptions& o, double time) {
  NestOptions nest = o.nest;
  if (o.centre.size() == 3) nest.centre = glm::dvec3(o.centre[0], o.centre[1], o.centre[2]);
  nest.levels = o.generator.levels;
  nest.time = time;
  return nest;
}

Dataset generate(const GenOptions& o, double time) {
  if (isNest(o)) return generateNest(nestOptions(o, time));
  BuiltinOptions generator = o.generator;
  generator.time = time;
  return generateBuiltin(o.kind, generator);
}

// What is written beside the path gen names, per format.
std::string companionsOf(const std::string& format) {
  if (format == "exa") return " and its .cells/.scalars files";
  if (format == "enzo") return " and its .hierarchy/.cpuNNNN files";
  return "";
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void writeOne(const GenOptions& o, double time, const std::string& out) {
  auto start = std::chrono::steady_clock::now();
  const Dataset dataset = generate(o, time);
  const double generateSeconds = secondsSince(start);
  start = std::chrono::steady_clock::now();
  const std::filesystem::path written = writeDataset(dataset, out, o.format);
  printLine(fmt::format("generated  {}: {} cells, levels {}..{} [{:.2f} s]", dataset.source(),
                        withCommas(dataset.cellCount()), dataset.finestLevel(),
                        dataset.coarsestLevel(), generateSeconds));
  printLine(fmt::format("wrote      {}{} [{:.2f} s]", written.string(), companionsOf(o.format),
                        secondsSince(start)));
}

// nest and the other kinds take different sizes: a size given to a kind that does not take it
// is refused rather than ignored, and only nest takes more than kMaxBuiltinLevels levels.
void checkKindOptions(const CLI::App& command, const GenOptions& o) {
  for (const char* flag : {"--root-cells", "--block-cells", "--centre", "--max-speed"})
    if (!isNest(o) && command.count(flag) > 0)
      throw InputError(flag, fmt::format("sizes kind nest only, not {}", o.kind));
  for (const char* flag : {"--root-blocks", "--target-cells", "--seed"})
    if (isNest(o) && command.count(flag) > 0)
      throw InputError(flag,
                       "does not apply to kind nest (sized by --levels, --root-cells and "
                       "--block-cells)");
  if (!isNest(o) && o.generator.levels > kMaxBuiltinLevels)
    throw InputError("--levels",
                     fmt::format("{} is outside the range 1 to {} of kind {} (nest "
                                 "takes up to {})",
                                 o.generator.levels, kMaxBuiltinLevels, o.kind, kMaxNestLevels));
}

// gen reads nothing and names every file apart: what is left to check before the work is the
// size and that the first file can be written (its directory exists, it is no directory).
void checkOutputs(const GenOptions& o) {
  if (isNest(o))
    checkGeneratedCells(nestCellCount(nestOptions(o, o.generator.time)), "--root-cells");
  else
    checkBuiltinSize(o.generator);
  const std::filesystem::path first =
      writtenPath(o.series == 0 ? o.out : fmt::format("{}_0000", o.out), o.format);
  if (o.format != "amrex") return RunFiles().checkOutput("--out", first);
  // A plotfile is a folder, replaced whole: its parent must be one.
  std::error_code error;
  const std::filesystem::path parent = first.parent_path().empty() ? "." : first.parent_path();
  if (!std::filesystem::is_directory(parent, error))
    throw InputError("--out", fmt::format("{} is not a folder", parent.string()));
}

void runGen(const CLI::App& command, const GenOptions& o) {
  checkKindOptions(command, o);
  checkOutputs(o);
  if (o.series == 0) return writeOne(o, o.generator.time, o.out);
  for (int i = 0; i < o.series; ++i)
    writeOne(o, o.generator.time + i * o.interval, fmt::format("{}_{:04d}", o.out, i));
}

}  // namespace

void addGenCommand(CLI::App& app) {
  auto options = std::make_shared<GenOptions>();
  std::string kinds;
  for (const std::string& k : builtinKinds()) kinds += (kinds.empty() ? "" : ", ") + k;
  CLI::App* command = app.add_subcommand(
      "gen", "write a synthetic dataset as ExaBricks, FLASH, Enzo or AMReX files");
  command->add_option("kind", options->kind, "dataset kind: " + kinds)->required();
  command->add_option("--out", options->out, "output prefix: writes PREFIX.exa, PREFIX.cells, ...")
      ->required();
  command
      ->add_option("--format", options->format,
                   "exa: PREFIX.exa with .cells/.scalars; flash: PREFIX.h5; enzo: PREFIX, "
                   "PREFIX.hierarchy, PREFIX.cpuNNNN; amrex: the plotfile folder PREFIX.plt")
      ->capture_default_str()
      ->check(CLI::IsMember(writableFormats()));
  addGeneratorOptions(*command, options->generator, "--seed", kMaxNestLevels);
  command
      ->add_option("--root-cells", options->nest.rootCells,
                   "nest: coarsest cells per axis over the domain")
      ->capture_default_str()
      ->check(countIn(1, std::numeric_limits<int>::max()));
  command
      ->add_option("--block-cells", options->nest.blockCells,
                   "nest: cells per axis of each finer level's cube (even; 2: an octree refined "
                   "towards the centre, at least 4: proper nesting)")
      ->capture_default_str()
      ->check(countIn(1, std::numeric_limits<int>::max()));
  command
      ->add_option("--centre", options->centre,
                   "nest: x,y,z, the nest's centre as a fraction of the unit domain [default "
                   "0.45,0.55,0.47]")
      ->delimiter(',')
      ->expected(3)
      ->check(finiteFloat());
  command
      ->add_option("--max-speed", options->nest.maxSpeed,
                   "nest: the spiral's speed capped at S domain widths per unit time [default "
                   "none]")
      ->check(positiveDouble());
  command
      ->add_option("--series", options->series,
                   "write N snapshots PREFIX_0000.exa, ... at --time, --time + --interval, ...")
      ->check(countIn(1, kMaxSeriesSnapshots));
  command->add_option("--interval", options->interval, "time between the snapshots of --series")
      ->capture_default_str()
      ->check(positiveDouble());
  command->callback([command, options] { runGen(*command, *options); });
}

}  // namespace amrstream::cli
