#pragma once
// What a prepared job and its traced lines hold (include/amrstream/trace_job.hpp), for the
// library's drivers (one process, MPI, the viewer) and the Python module.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "amrstream/trace_job.hpp"
#include "api/handles.hpp"
#include "api/held_traces.hpp"
#include "flow/seeds.hpp"
#include "flow/trace_options.hpp"
#include "output/vtk_field_data.hpp"

namespace amrstream {

struct PreparedJob::Impl {
  explicit Impl(Field built) : field(std::move(built)) {}
  Field field;  // with the dataset where it is kept
  flow::SeedList seeds;
  std::string seedDescription;
  flow::TraceOptions options;  // as checked against the field
  BackendRequest backend;
  std::unique_ptr<DeviceOpening> opening;  // its device, opened while the input was read
  TraceReport report;                      // filled by tracing
  std::uint64_t cellCount = 0;  // of the input (the field's volume may hold periodic images)

  flow::VectorVolume& volume() { return volumeOf(field); }
  // The dataset; InputError-free: callers ask only where it was kept.
  const bricks::AmrField& cells() const { return cellsOf(*field.dataset()); }
  // Frees the dataset (the largest part of a big input) and the volume's map from value slots to
  // cells when nothing after needs them: tracing reads the volume alone.
  void releaseDataset();
};

struct TracedLines::Impl {
  explicit Impl(Field traced) : field(std::move(traced)) {}
  std::unique_ptr<HeldTraces> held;
  Field field;  // keeps the volume the held traces may point into
  std::vector<output::FieldDataArray> provenance;
  TraceReport report;
  flow::StepMode stepMode = flow::StepMode::Arc;
};

// The provenance of lines traced by `job` (the .vtp's FieldData).
std::vector<output::FieldDataArray> jobProvenance(const PreparedJob::Impl& job);

// Writes `traces` as a .vtp with `provenance`, timing it.
WrittenLines writeLines(const flow::TraceView& traces, const TraceOutput& output,
                        std::vector<output::FieldDataArray> provenance);

// The "output" line of a written .vtp.
std::string outputLine(const std::filesystem::path& path, const WrittenLines& written);

// The "steps", "reasons" and "time" lines of a trace, whose lines and steps it counts into
// `report`.
void sayTraceSummary(const flow::TraceSet& lines, TraceReport& report, const Log& log);

// "out of domain (1): 12, max steps (5): 244": how many lines ended for each reason.
std::string reasonHistogram(std::span<const std::int32_t> reasons);

// The "memory" line: the host's peak resident memory, and with `stagePeak` the peak since the
// stage began (util/peak_memory.hpp), with `tracingPeak` the tracing stage's apart.
std::string memoryLine(bool stagePeak, std::optional<std::uint64_t> tracingPeak = std::nullopt);

}  // namespace amrstream
