#include "gen_command.hpp"

#include <fmt/format.h>

#include <memory>

#include "dataset_options.hpp"
#include "formats/exa_format.hpp"
#include "synth/generators.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct GenOptions {
  std::string kind;
  std::string out;
  synth::GeneratorOptions generator;
};

void runGen(const GenOptions& o) {
  Stopwatch clock;
  const bricks::AmrField field = synth::generate(o.kind, o.generator);
  const double generateSeconds = clock.seconds();
  clock.restart();
  const std::filesystem::path exa = formats::writeExa(field, o.out);
  fmt::print("generated  {}: {} cells, levels {}..{} [{:.2f} s]\n", field.source(),
             withCommas(field.cellCount()), field.finestLevel(), field.coarsestLevel(),
             generateSeconds);
  fmt::print("wrote      {} and its .cells/.scalars files [{:.2f} s]\n", exa.string(),
             clock.seconds());
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
  command->callback([options] { runGen(*options); });
}

}  // namespace amrstream::cli
