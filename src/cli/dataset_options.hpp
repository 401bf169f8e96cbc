#pragma once
// Options shared by the commands that open a dataset: the input and the sizes of builtin data.

#include <CLI/CLI.hpp>
#include <string>

#include "synth/generators.hpp"

namespace amrstream::cli {

struct DatasetOptions {
  std::string input;
  synth::GeneratorOptions generator;
};

// Adds the positional INPUT and the --levels, --root-blocks, --target-cells and `seedFlag`
// options of builtin datasets.
void addDatasetOptions(CLI::App& command, DatasetOptions& options, const std::string& seedFlag);
// The same options without INPUT, --levels taking 1 to `maxLevels`.
void addGeneratorOptions(CLI::App& command, synth::GeneratorOptions& options,
                         const std::string& seedFlag, int maxLevels);

// Throws InputError naming --target-cells when the cells of a builtin dataset (`--target-cells`,
// or all cells of fully refined levels if fewer) cannot fit in the memory traces may take: called
// before generating. Inputs other than builtin:KIND are not checked.
void checkBuiltinSize(const DatasetOptions& options);
void checkGeneratorSize(const synth::GeneratorOptions& generator);
// The same for `cells` generated cells, naming `option`.
void checkGeneratedCells(double cells, const std::string& option);

// "1234567" -> "1,234,567".
std::string withCommas(std::size_t n);

}  // namespace amrstream::cli
