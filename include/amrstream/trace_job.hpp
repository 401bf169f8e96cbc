#pragma once
// The trace job, from input to written lines: the dataset, the field, the seeds, the stepping and
// the backend, prepared (read, built, seeded and checked), traced, and written. The command line,
// the Python module, the viewer and the MPI drivers all run it through these functions; each says
// what it read, chose and measured as lines on a Reporter.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "amrstream/backend.hpp"
#include "amrstream/builtin.hpp"
#include "amrstream/field.hpp"
#include "amrstream/log.hpp"
#include "amrstream/run_files.hpp"
#include "amrstream/seeding.hpp"
#include "amrstream/trace_settings.hpp"
#include "amrstream/tracing.hpp"

namespace amrstream {

// A dataset to load: a file (see load) or builtin:KIND sized by `builtin`.
struct DatasetRequest {
  std::string input;
  BuiltinOptions builtin;
  DeclaredUnits units;  // length_unit, unit
};

struct TraceJob {
  DatasetRequest dataset;
  FieldOptions field;
  SeedRequest seeds;
  std::string seedsOut;  // write the seeds used here, one "x y z" per line (empty: not)
  TraceSettings trace;
  BackendRequest backend;
};

// The files a job reads (the dataset's, the seeds file) and its seedsOut, checked: callers add
// their own outputs before any work. Also checks the size of a builtin dataset and the seed count.
RunFiles jobFiles(const TraceJob& job);

struct PrepareOptions {
  bool seeds = true;  // false: stop after the field (for traces read from a file)
  // Whether the field keeps the dataset (rendering and the viewer read its channels). Without
  // it, an .exa's channels are read one at a time as the field takes them.
  KeepDataset dataset = KeepDataset::No;
  // Whether trace() follows: the tracing backend's device is then opened on a thread of its own
  // while the input is read and the volume built.
  bool openDevice = false;
};

// A job made ready to trace. Move-only.
class PreparedJob {
 public:
  const Field& field() const;
  std::span<const glm::dvec3> seeds() const;
  const std::string& seedDescription() const;  // e.g. "random (seed 1) in the cells of a box"
  std::string stepMode() const;                // as resolved: "arc", "cell" or "time"

  struct Impl;  // the library's: src/api/job_state.hpp
  explicit PreparedJob(std::unique_ptr<Impl> impl);
  PreparedJob(PreparedJob&&) noexcept;
  PreparedJob& operator=(PreparedJob&&) noexcept;
  ~PreparedJob();
  Impl& impl() const { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// Loads the dataset, builds the field, chooses and checks the seeds (writing seedsOut) and the
// stepping. Says "input", "structure", "point data", "seeds" and "stepping" lines. Throws
// InputError naming the setting or file at fault.
PreparedJob prepare(const TraceJob& job, const PrepareOptions& options = {},
                    const Reporter& reporter = {});

// A job on a field already built, with given seeds (physical coordinates; those on the domain's
// upper faces are moved just inside): what the Python module traces. Throws InputError for a seed
// outside the domain or a bad setting.
PreparedJob prepare(const Field& field, std::vector<glm::dvec3> seeds,
                    const TraceSettings& settings, const BackendRequest& backend,
                    std::string seedDescription = "given points");

// Where a GPU trace's points wait until they are written: in host memory, or on the device that
// traced them, copied out as they are written. Auto keeps them on a GPU (not a software device)
// where every line's points fit.
enum class TraceStore { Auto, Host, Device };

// What happens to the field's host values once a GPU backend has uploaded them: Release frees
// them when nothing after tracing reads them (not with a CPU tail, which the CPU finishes).
enum class HostValues { Keep, Release };

struct TraceRunOptions {
  TraceStore store = TraceStore::Host;
  HostValues hostValues = HostValues::Keep;
};

// Lines traced and held for a writer, their points where the run's store put them.
class TracedLines {
 public:
  const TraceReport& report() const;
  // Writes them as a .vtp with their provenance; says the "output" line.
  WrittenLines write(const TraceOutput& output, const Log& log = {}) const;
  // The lines with their points in host memory (TraceStore::Host only).
  Traces assemble() &&;

  struct Impl;  // the library's: src/api/job_state.hpp
  explicit TracedLines(std::unique_ptr<Impl> impl);
  TracedLines(TracedLines&&) noexcept;
  TracedLines& operator=(TracedLines&&) noexcept;
  ~TracedLines();

 private:
  std::unique_ptr<Impl> impl_;
};

// Traces the prepared seeds with the job's backend. Progress: stage "tracing", seeds. Says the
// backend chosen, the device setup, where a GPU trace's host time went, and the "steps",
// "reasons" and "time" lines. Throws vk::ContextError (a std::runtime_error) naming what a named
// backend lacks.
TracedLines trace(PreparedJob& job, const TraceRunOptions& options = {},
                  const Reporter& reporter = {});

// What a trace job did: what it read, traced and wrote, and where (TraceReport).
struct TraceJobSummary {
  std::string input;
  std::uint64_t cells = 0, seeds = 0, lines = 0, steps = 0, pointsWritten = 0;
  TraceReport report;
};

// `amrstream trace` in one process: prepare (the dataset released once the field holds what
// tracing reads), trace (`store` for the points), write, then the host memory's peak ("memory").
// With a clock on `reporter`, its stages are lapped as they end (input, layout, bricks, regions,
// seeds, values, the device's setup, tracing, output, freeing) and the "wall" line ends the run.
TraceJobSummary runTraceJob(const TraceJob& job, const TraceOutput& output, TraceStore store,
                            const Reporter& reporter = {});

// Writes the summary and the clock's stages to `path` as JSON, whole or not at all; throws
// std::runtime_error naming the path when it cannot.
void writeTraceJson(const std::filesystem::path& path, const TraceJobSummary& summary,
                    const StageClock& clock);

}  // namespace amrstream
