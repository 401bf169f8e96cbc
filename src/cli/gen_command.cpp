#include "gen_command.hpp"

#include <fmt/format.h>

#include <memory>

#include "dataset_options.hpp"
#include "option_checks.hpp"
#include "option_limits.hpp"
#include "output_paths.hpp"
#include "formats/exa_format.hpp"
#include "synth/generators.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct GenOptions {
  std::string kind;
  std::string out;
  synth::GeneratorOptions generator;
  int series = 0;         // snapshots; 0: one dataset named by --out alone
  double interval = 0.1;  // time between snapshots
};

void writeOne(const std::string& kind, const synth::GeneratorOptions& generator,
              const std::string& out) {
  Stopwatch clock;
  const bricks::AmrField field = synth::generate(kind, generator);
  const double generateSeconds = clock.seconds();
  clock.restart();
  const std::filesystem::path exa = formats::writeExa(field, out);
  fmt::print("generated  {}: {} cells, levels {}..{} [{:.2f} s]\n", field.source(),
             withCommas(field.cellCount()), field.finestLevel(), field.coarsestLevel(),
             generateSeconds);
  fmt::print("wrote      {} and its .cells/.scalars files [{:.2f} s]\n", exa.string(),
             clock.seconds());
}

// gen reads nothing and names every file apart: what is left to check before the work is the
// size and that the first file can be written (its directory exists, it is no directory).
void checkOutputs(const GenOptions& o) {
  checkGeneratorSize(o.generator);
  const std::string first = o.series == 0 ? o.out + ".exa" : fmt::format("{}_0000.exa", o.out);
  RunFiles().checkOutput("--out", first);
}

void runGen(const GenOptions& o) {
  checkOutputs(o);
  if (o.series == 0) return writeOne(o.kind, o.generator, o.out);
  for (int i = 0; i < o.series; ++i) {
    synth::GeneratorOptions snapshot = o.generator;
    snapshot.time = o.generator.time + i * o.interval;
    writeOne(o.kind, snapshot, fmt::format("{}_{:04d}", o.out, i));
  }
}

}  // namespace

void addGenCommand(CLI::App& app) {
  auto options = std::make_shared<GenOptions>();
  std::string kinds;
  for (const std::string& k : synth::generatorKinds()) kinds += (kinds.empty() ? "" : ", ") + k;
  CLI::App* command = app.add_subcommand("gen", "write a synthetic dataset as ExaBricks files");
  command->add_option("kind", options->kind, "dataset kind: " + kinds)->required();
  command->add_option("--out", options->out, "output prefix: writes PREFIX.exa, PREFIX.cells, ...")
      ->required();
  addGeneratorOptions(*command, options->generator, "--seed");
  command
      ->add_option("--series", options->series,
                   "write N snapshots PREFIX_0000.exa, ... at --time, --time + --interval, ...")
      ->check(countIn(1, kMaxSeriesSnapshots));
  command->add_option("--interval", options->interval, "time between the snapshots of --series")
      ->capture_default_str()
      ->check(positiveDouble());
  command->callback([options] { runGen(*options); });
}

}  // namespace amrstream::cli
