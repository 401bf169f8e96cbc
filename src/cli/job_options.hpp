#pragma once
// The options of the trace job that `trace`, `render` and `view` share: the dataset, the vector
// and its frame, the point data, the seeding, the stepping and the backend.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>
#include <vector>

#include "amrstream/field.hpp"
#include "amrstream/seeding.hpp"
#include "amrstream/trace_job.hpp"

namespace amrstream::cli {

// The seeding options (--seeds, --seed-box, --seed-line, --seed-grid, --seed-density, --count,
// ..., and --seeds-out unless `seedsOut` is null) and the field options (--vector, --point-data,
// --periodic, --interpolant).
void addSeedOptions(CLI::App& command, SeedRequest& seeds, std::string* seedsOut);
void addFieldOptions(CLI::App& command, FieldOptions& field);
// --frame-velocity: for the commands that trace or sample one snapshot (not pathlines).
void addFrameVelocityOption(CLI::App& command, FieldOptions& field);
// --backend and --device.
void addBackendOptions(CLI::App& command, BackendRequest& backend);

// Adds the options above (INPUT included) and the stepping options to `command`; `defaultCount`
// is --count's default. The seeding options are listed in --help under "Seeds", the stepping
// options under "Tracing".
void addTraceJobOptions(CLI::App& command, TraceJob& options, std::size_t defaultCount = 256);

// The seeding and stepping options given on `command`'s line ("--count", "--steps"), which do
// nothing where the lines are not traced (render --traces).
std::vector<std::string> givenTracingOptions(const CLI::App& command);

}  // namespace amrstream::cli
