#pragma once
// Options shared by the commands that open a dataset: the input and the sizes of builtin data.

#include <CLI/CLI.hpp>
#include <string>

#include "amrstream/builtin.hpp"
#include "amrstream/trace_job.hpp"

namespace amrstream::cli {

// Whether a command takes --length-unit and --unit: those whose outputs show or keep units.
enum class DeclaresUnits { No, Yes };

// Adds the positional INPUT, the --levels, --root-blocks, --target-cells and `seedFlag` options
// of builtin datasets and, for commands that declare units, --length-unit and --unit.
void addDatasetOptions(CLI::App& command, DatasetRequest& options, const std::string& seedFlag,
                       DeclaresUnits units = DeclaresUnits::Yes);
// --length-unit and --unit NAME=UNIT.
void addUnitOptions(CLI::App& command, DeclaredUnits& units);
// The same options without INPUT, --levels taking 1 to `maxLevels`.
void addGeneratorOptions(CLI::App& command, BuiltinOptions& options, const std::string& seedFlag,
                         int maxLevels);

}  // namespace amrstream::cli
