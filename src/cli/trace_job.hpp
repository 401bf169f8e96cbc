#pragma once
// What `trace`, `render` and `view` share: the dataset, the vector, the point data, the seeding
// and the stepping options, and the run from input to traces with its summary lines on stdout.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "amrstream/field.hpp"
#include "amrstream/seeding.hpp"
#include "amrstream/trace_settings.hpp"
#include "amrstream/tracing.hpp"
#include "bricks/amr_field.hpp"
#include "dataset_options.hpp"
#include "flow/seeds.hpp"
#include "flow/trace_options.hpp"
#include "flow/trace_set.hpp"
#include "flow/vector_volume.hpp"
#include "formats/value_window.hpp"
#include "output_paths.hpp"
#include "progress.hpp"

namespace amrstream::cli {

struct TraceJobOptions {
  DatasetOptions dataset;
  FieldOptions field;
  SeedRequest seeds;
  std::string seedsOut;
  TraceSettings trace;
  BackendRequest backend;
};

// The seeding options (--seeds, --seed-box, --seed-line, --seed-grid, --seed-density, --count,
// ..., and --seeds-out unless `seedsOut` is null) and the field options (--vector, --point-data,
// --periodic, --interpolant).
void addSeedOptions(CLI::App& command, SeedRequest& seeds, std::string* seedsOut);
void addFieldOptions(CLI::App& command, FieldOptions& field);

// Adds the options above (INPUT included) to `command`; `defaultCount` is --count's default.
void addTraceJobOptions(CLI::App& command, TraceJobOptions& options,
                        std::size_t defaultCount = 256);

// What the job reads (the dataset's files, the seeds file) and its --seeds-out, checked
// (RunFiles): the caller adds its own inputs and outputs before any work. Also checks the size of
// a builtin dataset (checkBuiltinSize) and the seed count (checkSeedRequest).
RunFiles jobFiles(const TraceJobOptions& o);

// The input loaded and prepared for tracing.
struct PreparedInput {
  // The cells; released by `trace` once the volume holds what it needs (see releaseField), and
  // never held with CellsAfter::Release.
  std::shared_ptr<const bricks::AmrField> cells;
  bricks::DatasetInfo info;  // what the input says of itself, kept when the cells go
  std::string source;        // the input's name
  flow::VectorVolume volume;
  flow::SeedList seeds;
  std::string seedDescription;
  flow::TraceOptions options;  // keepHistory set; the caller may change it
  TraceReport report;          // filled by runTraces

  const bricks::AmrField& field() const { return *cells; }
  // Frees the cells (the largest part of a big input) and the volume's map from value slots to
  // cells when nothing after needs them: tracing reads the volume alone.
  void releaseField() {
    cells.reset();
    std::vector<std::uint32_t>().swap(volume.cellIds);
  }
};

// Whether the caller needs the cells once the volume and the seeds are made (render and view
// colour by channels and show them) or not (trace): then an .exa's channels are read one at a
// time while the volume takes them, after the cells are freed, and PreparedInput::cells stays
// empty.
enum class CellsAfter { Keep, Release };

// An MPI rank's share of the input over data: the values of `window` alone (formats that read
// part of their values; the other cells' values are 0), and density seeds chosen with the other
// ranks from the cells `markOwned` marks as this rank's (one rank's each), called once the
// input is read and only for density seeds.
struct InputShare {
  formats::ValueWindow window;
  std::function<void(const bricks::AmrField&, std::vector<std::uint8_t>& owned)> markOwned;
  flow::SharedCells cells;  // sumCounts and gatherCells set by the caller
  std::vector<std::uint8_t> owned;
  // When given, the volume's layout built from the same cells (and how long it took): only the
  // values are filled in.
  std::optional<flow::VectorVolume> layout;
  flow::VolumeBuildTimes layoutTimes;
  formats::WindowedRead read;  // what was read
};

// Loads the input, builds bricks and regions, chooses and checks the seeds and the stepping,
// printing the input, structure, seeds and stepping lines. Without `withSeeds`, stops after the
// structure (for traces read from a file).
PreparedInput prepareInput(const TraceJobOptions& o, bool withSeeds = true,
                           CellsAfter after = CellsAfter::Keep, InputShare* share = nullptr);

// Traces with the requested backend (with a progress line) and records what ran in
// input.report. The points stay in the rounds that made them.
flow::StoredTraces traceSeeds(const TraceJobOptions& o, PreparedInput& input,
                              HostValues hostValues = HostValues::Keep);

// The steps, reasons and time lines of a trace.
void printTraceSummary(const flow::TraceSet& traces, const TraceReport& report);

// traceSeeds(), then printTraceSummary(). The points stay in the rounds that made them
// (StoredTraces::assemble() gives a TraceSet).
flow::StoredTraces runTraces(const TraceJobOptions& o, PreparedInput& input,
                             HostValues hostValues = HostValues::Keep);

// runTraces() for a writer: the points kept where `store` says (see traceForWriting).
std::unique_ptr<HeldTraces> runTracesForWriting(const TraceJobOptions& o, PreparedInput& input,
                                                TraceStore store, HostValues hostValues);

// Prints a line of the library's log on stdout.
void printLine(const std::string& line);
// The same, taking `progress`'s line off the terminal first.
Log printLineAfter(Progress& progress);

// "out of domain (1): 12, max steps (5): 244": how many lines ended for each reason.
std::string reasonHistogram(std::span<const std::int32_t> reasons);

}  // namespace amrstream::cli
