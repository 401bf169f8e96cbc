#include "convert_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "dataset_files.hpp"
#include "dataset_options.hpp"
#include "formats/exa/exa_format.hpp"
#include "formats/load_input.hpp"
#include "output_paths.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct ConvertOptions {
  DatasetOptions dataset;
  std::string out;
};

// writeExa's files for PREFIX: PREFIX.exa, PREFIX.cells and PREFIX.NAME.scalars per channel.
std::filesystem::path exaFile(const std::filesystem::path& prefix, const std::string& suffix) {
  return prefix.parent_path() / (prefix.filename().string() + suffix);
}

void runConvert(const ConvertOptions& o) {
  checkBuiltinSize(o.dataset);
  std::filesystem::path prefix(o.out);
  if (prefix.extension() == ".exa") prefix.replace_extension();
  RunFiles files;
  files.addInputs(datasetFiles(o.dataset.input));
  files.addOutput("OUT", exaFile(prefix, ".exa"));
  files.addOutput("OUT's cells", exaFile(prefix, ".cells"));

  Stopwatch clock;
  const formats::Format format = formats::detectFormat(o.dataset.input);
  const bricks::AmrField field = formats::loadInput(o.dataset.input, o.dataset.generator);
  // The channels' names are known now, still before anything is written.
  for (const bricks::Channel& channel : field.channels())
    files.addOutput("OUT's scalars", exaFile(prefix, "." + channel.name + ".scalars"));
  fmt::print("read       {} ({}): {} cells, levels {}..{}, {} channels [{:.2f} s]\n",
             field.source(), formats::formatName(format), withCommas(field.cellCount()),
             field.finestLevel(), field.coarsestLevel(), field.channels().size(), clock.seconds());
  clock.restart();
  const std::filesystem::path exa = formats::writeExa(field, prefix);
  fmt::print("wrote      {} and its .cells/.scalars files [{:.2f} s]\n", exa.string(),
             clock.seconds());
}

}  // namespace

void addConvertCommand(CLI::App& app) {
  auto options = std::make_shared<ConvertOptions>();
  CLI::App* command = app.add_subcommand("convert", "write any input as ExaBricks files");
  addDatasetOptions(*command, options->dataset, "--gen-seed");
  command->add_option("out", options->out, "output OUT.exa (also writes OUT.cells, ...)")
      ->required();
  command->callback([options] { runConvert(*options); });
}

}  // namespace amrstream::cli
