#pragma once
// What `pathlines` and the viewer's series playback share: reading a snapshot of a series and
// building its field, the checks every later snapshot passes, and the tracer's options from the
// settings.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "amrstream/dataset.hpp"
#include "amrstream/field.hpp"
#include "amrstream/pathlines.hpp"
#include "flow/pathline_tracer.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

namespace gpu {
class VectorProbe;
}

struct LoadedSnapshot {
  double time = 0.0;
  std::optional<Field> field;
  std::optional<Dataset> cells;  // kept for the first only: density seeding reads them
  std::uint64_t cellCount = 0;
  double readSeconds = 0.0, buildSeconds = 0.0;
};

// Reads the snapshot and builds its field (on the heap: a GPU probe points at its volume, which
// must not move).
std::unique_ptr<LoadedSnapshot> loadSnapshot(const SnapshotFile& file, const FieldOptions& field,
                                             const DeclaredUnits& units, bool keepCells);

// "a,b,c", or "none".
std::string joinedNames(const std::vector<std::string>& names);

// Every snapshot must offer what the first one traced with: throws InputError naming `path`.
void checkLikeTheFirst(const flow::VectorVolume& v, const std::string& path,
                       const flow::VectorVolume& first);

// Indices of the snapshots bracketing [t0, t1].
std::pair<std::size_t, std::size_t> snapshotsUsed(std::span<const SnapshotFile> series, double t0,
                                                  double t1);

// The times of snapshots first..last (PathlineTracer::planStorage's).
std::vector<double> snapshotTimes(std::span<const SnapshotFile> series, std::size_t first,
                                  std::size_t last);

// Streaklines release every seed again every `releaseEvery`: refuses more particles than a
// trace may hold or its memory holds, or an interval the times cannot resolve. `seedCount` 0:
// the seeds are not chosen yet, and only the releases are checked.
void checkReleases(const flow::PathlineOptions& options, std::size_t seedCount,
                   std::size_t channelCount);

// The probe's samples as a snapshot's sampler (the CPU's sampler without one).
flow::VectorBatchSampler probeSampler(gpu::VectorProbe* probe);

// The tracer's options from the settings and the series, checked (settingError names the
// setting at fault).
flow::PathlineOptions pathlineOptions(std::span<const SnapshotFile> series,
                                      const PathlineSettings& settings);

}  // namespace amrstream
