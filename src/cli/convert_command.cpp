#include "convert_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <memory>

#include "amrstream/dataset.hpp"
#include "amrstream/run_files.hpp"
#include "console.hpp"
#include "dataset_options.hpp"

namespace amrstream::cli {

namespace {

// writeExaBricks' files for PREFIX: PREFIX.exa, PREFIX.cells and PREFIX.NAME.scalars per channel.
std::filesystem::path exaFile(const std::filesystem::path& prefix, const std::string& suffix) {
  return prefix.parent_path() / (prefix.filename().string() + suffix);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void runConvert(const DatasetRequest& input, const std::string& out) {
  if (input.input.starts_with("builtin:")) checkBuiltinSize(input.builtin);
  std::filesystem::path prefix(out);
  if (prefix.extension() == ".exa") prefix.replace_extension();
  RunFiles files;
  files.addInputs(datasetFiles(input.input));
  files.addOutput("OUT", exaFile(prefix, ".exa"));
  files.addOutput("OUT's cells", exaFile(prefix, ".cells"));
  auto start = std::chrono::steady_clock::now();
  const std::string format = formatName(input.input);
  const Dataset dataset = load(input.input, input.builtin, input.units);
  // The channels' names are known now, still before anything is written.
  for (const std::string& channel : dataset.channelNames())
    files.addOutput("OUT's scalars", exaFile(prefix, "." + channel + ".scalars"));
  printLine(fmt::format("read       {} ({}): {} cells, levels {}..{}, {} channels [{:.2f} s]",
                        dataset.source(), format, withCommas(dataset.cellCount()),
                        dataset.finestLevel(), dataset.coarsestLevel(),
                        dataset.channelNames().size(), secondsSince(start)));
  start = std::chrono::steady_clock::now();
  const std::filesystem::path exa = writeExaBricks(dataset, prefix);
  printLine(fmt::format("wrote      {} and its .cells/.scalars files [{:.2f} s]", exa.string(),
                        secondsSince(start)));
}

}  // namespace

void addConvertCommand(CLI::App& app) {
  auto input = std::make_shared<DatasetRequest>();
  auto out = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand("convert", "write any input as ExaBricks files");
  addDatasetOptions(*command, *input, "--gen-seed");
  command->add_option("out", *out, "output OUT.exa (also writes OUT.cells, ...)")->required();
  command->callback([input, out] { runConvert(*input, *out); });
}

}  // namespace amrstream::cli
