#pragma once
// Pathlines and streaklines through a time series of snapshots (docs/architecture.md,
// "Pathlines"): the snapshots are listed and ordered by the times their files state, then read
// and built one at a time, the next on another thread while the current interval is traced, so at
// most three are in memory whatever the series' length.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "amrstream/backend.hpp"
#include "amrstream/dataset_info.hpp"
#include "amrstream/field.hpp"
#include "amrstream/log.hpp"
#include "amrstream/seeding.hpp"
#include "amrstream/tracing.hpp"

namespace amrstream {

struct SnapshotFile {
  std::string path;
  double time = 0.0;
};

// Expands the glob patterns, reads each snapshot's time from its metadata and sorts by time.
// Throws InputError naming the file that states no time, two files at the same time, or fewer
// than two snapshots.
std::vector<SnapshotFile> listSnapshots(std::span<const std::string> patterns);

struct PathlineSettings {
  std::optional<double> startTime;   // default: the first snapshot's time
  std::optional<double> endTime;     // default: the last snapshot's time
  std::optional<double> stepSize;    // physical time; default: the shortest interval used / 10
  double releaseEvery = 0.0;         // > 0: streaklines, new particles at this interval
  std::uint64_t maxResultBytes = 0;  // 0: a share of the machine's memory
};

struct PathlineJob {
  std::vector<SnapshotFile> series;  // listSnapshots'
  FieldOptions field;                // without frameVelocity, which tracePathlines refuses
  SeedRequest seeds;                 // chosen on the snapshot at or before the start time
  PathlineSettings settings;
  BackendRequest backend;
  DeclaredUnits units;  // length_unit, unit: declared for every snapshot (as load's)
};

// Where the time went: reading and building every snapshot (on the loading thread, except the
// first), tracing, and waiting for a snapshot that was not ready when tracing needed it.
struct PathlineReport {
  std::string backend;         // "cpu", "compute", ...
  std::string device;          // the Vulkan device's name, or the CPU's thread count
  double deviceSeconds = 0.0;  // GPU backends: the context, kernels, uploads and structures
  // GPU backends, within traceSeconds: the samples' batches, writing their points, waiting for
  // the device and reading the samples.
  std::size_t probeCalls = 0;
  double probeWriteSeconds = 0.0, probeDeviceSeconds = 0.0, probeReadSeconds = 0.0;
  // GPU backends, within traceSeconds: the particles' steps on the device, in rounds of
  // dispatches, waiting for them and storing their points on the host.
  std::size_t stepRounds = 0, stepDispatches = 0;
  double stepDeviceSeconds = 0.0, stepCollectSeconds = 0.0;
  std::size_t snapshotsUsed = 0;
  std::uint64_t cellsRead = 0;
  double readSeconds = 0.0, buildSeconds = 0.0, traceSeconds = 0.0, waitSeconds = 0.0;
  double wallSeconds = 0.0;
  std::uint64_t steps = 0;
  // As resolved from the settings.
  double stepSize = 0.0, startTime = 0.0, endTime = 0.0, releaseEvery = 0.0;
  std::size_t seedCount = 0, particleCount = 0;
  std::string seedDescription;
  std::string vectorName;
  std::vector<std::string> channelNames;
  std::string interpolant;
  DatasetInfo firstInfo;  // what the first snapshot used says of itself
};

struct PathlineResult {
  Traces lines;  // pathlines, or with releaseEvery streaklines (one per seed)
  PathlineReport report;
  bool streaklines = false;
};

// Traces particles released from the seeds through the series. With a GPU backend each snapshot
// is uploaded with its point-location structure and the RK4 stages' samples are taken on the
// device; the host does the rest. Progress: stage "intervals". Says the "series", "seeds" and
// "tracing" lines, then "stepping", "particles", "time" and, on a GPU, "samples". Throws
// InputError for a start or end time outside the series, a snapshot that lacks the vector or a
// point-data channel, or seeds outside the domain.
PathlineResult tracePathlines(const PathlineJob& job, const Reporter& reporter = {});

// `amrstream pathlines`: tracePathlines, then the lines written ("output") and the host memory's
// peak ("memory").
void runPathlineJob(const PathlineJob& job, const TraceOutput& output,
                    const Reporter& reporter = {});

}  // namespace amrstream
