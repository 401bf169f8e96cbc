#include "convert_command.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "dataset_options.hpp"
#include "formats/exa_format.hpp"
#include "formats/load_input.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

struct ConvertOptions {
  DatasetOptions dataset;
  std::string out;
};

void runConvert(const ConvertOptions& o) {
  Stopwatch clock;
  const formats::Format format = formats::detectFormat(o.dataset.input);
  const bricks::AmrField field = formats::loadInput(o.dataset.input, o.dataset.generator);
  fmt::print("read       {} ({}): {} cells, levels {}..{}, {} channels [{:.2f} s]\n",
             field.source(), formats::formatName(format), withCommas(field.cellCount()),
             field.finestLevel(), field.coarsestLevel(), field.channels().size(), clock.seconds());
  clock.restart();
  std::filesystem::path prefix(o.out);
  if (prefix.extension() == ".exa") prefix.replace_extension();
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
