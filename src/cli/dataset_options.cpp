#include "dataset_options.hpp"

namespace amrstream::cli {

void addGeneratorOptions(CLI::App& command, synth::GeneratorOptions& options,
                         const std::string& seedFlag) {
  command.add_option("--levels", options.levels, "AMR levels of a generated dataset")
      ->capture_default_str();
  command
      .add_option("--root-blocks", options.rootBlocks,
                  "root blocks (of 8^3 cells) per axis of a generated dataset")
      ->capture_default_str();
  command.add_option("--target-cells", options.targetCells, "cell budget of a generated dataset")
      ->capture_default_str();
  command.add_option(seedFlag, options.seed, "random seed of a generated dataset")
      ->capture_default_str();
  command.add_option("--time", options.time, "snapshot time of a generated unsteady dataset (swirl)")
      ->capture_default_str();
}

void addDatasetOptions(CLI::App& command, DatasetOptions& options, const std::string& seedFlag) {
  std::string kinds;
  for (const std::string& kind : synth::generatorKinds())
    kinds += (kinds.empty() ? "" : "|") + kind;
  command
      .add_option("input", options.input,
                  "the dataset: a FLASH HDF5 plotfile or checkpoint, an Enzo parameter file (or "
                  "its .hierarchy, .harrays or .cpuNNNN), an AMReX plotfile directory, a Gerris "
                  "text dump, an ExaBricks .exa file, or builtin:" +
                      kinds)
      ->required();
  addGeneratorOptions(command, options.generator, seedFlag);
}

std::string withCommas(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace amrstream::cli
