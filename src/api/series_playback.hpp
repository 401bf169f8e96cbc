#pragma once
// Pathlines through a series of snapshots that grow a frame at a time: `amrstream view` plays a
// series with them. Each advance() moves the particles by some time steps within the current
// interval (flow::PathlineTracer::advance with a stop), so that the lines equal those of
// `pathlines`; at the interval's end the later snapshot becomes the earlier one, and the next,
// read and built on another thread while the interval played, the later.

#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "amrstream/pathlines.hpp"
#include "api/pathline_setup.hpp"
#include "flow/growing_traces.hpp"
#include "flow/pathline_tracer.hpp"
#include "gpu/backend.hpp"

namespace amrstream {

namespace vk {
class Context;
}
namespace gpu {
struct TraceKernel;
struct VolumeBuffers;
class PathlineStepper;
class VectorProbe;
}  // namespace gpu

class SeriesPlayback final : public flow::GrowingTraces {
 public:
  // `first`: the field of the snapshot at or before options.startTime, built with `field`
  // (the caller's, which must outlive the playback). `seeds` in physical coordinates. With a
  // context the particles step on its device with `backend`'s kernels (`firstDevice`: `first`
  // already there, which must outlive the playback; else uploaded); without, on the CPU. Throws
  // InputError for a later snapshot that lacks the vector or a channel (when it is read).
  SeriesPlayback(std::vector<SnapshotFile> series, const flow::PathlineOptions& options,
                 FieldOptions field, DeclaredUnits units, const flow::VectorVolume& first,
                 std::span<const glm::dvec3> seeds, const vk::Context* ctx, gpu::Backend backend,
                 const gpu::VolumeBuffers* firstDevice = nullptr);
  ~SeriesPlayback() override;
  SeriesPlayback(const SeriesPlayback&) = delete;
  SeriesPlayback& operator=(const SeriesPlayback&) = delete;

  // Moves the particles by up to `steps` time steps, stopping at the current interval's end.
  std::size_t advance(std::uint32_t steps) override;
  bool finished() const override;
  std::size_t runningCount() const override { return tracer_.runningCount(); }
  std::size_t lineCount() const override { return tracer_.particleCount(); }
  std::size_t stepsTaken() const override { return std::size_t(tracer_.stepCount()); }
  const flow::TraceSet& traces() const override;
  const flow::TraceSet& recent() const override { return recent_; }

  double time() const { return time_; }  // where the last advance() stopped
  const flow::PathlineOptions& options() const { return options_; }
  // The current interval's earlier snapshot, 0 for the first; and how many intervals there are.
  std::size_t interval() const { return index_ - first_; }
  std::size_t intervalCount() const { return last_ - first_; }

 private:
  struct Device;
  // Starts reading the snapshot after the interval's later one, where there is one.
  void loadAhead();
  // The interval's later snapshot becomes the earlier, and the next one read the later.
  void nextInterval();
  flow::Snapshot snapshotA() const;
  flow::Snapshot snapshotB() const;

  std::vector<SnapshotFile> series_;
  flow::PathlineOptions options_;
  FieldOptions field_;
  DeclaredUnits units_;
  std::size_t first_ = 0, last_ = 0, index_ = 0;
  const flow::VectorVolume* firstVolume_;
  std::unique_ptr<LoadedSnapshot> a_, b_;  // a_ empty while the first interval plays
  std::future<std::unique_ptr<LoadedSnapshot>> next_;
  std::unique_ptr<Device> device_;
  flow::PathlineTracer tracer_;
  double time_;
  bool started_ = false, done_ = false;
  mutable flow::TraceSet traces_;
  mutable bool stale_ = true;
  flow::TraceSet recent_;
};

}  // namespace amrstream
