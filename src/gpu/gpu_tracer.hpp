#pragma once
// Streamline tracing on a Vulkan device with one of the GPU backends. Owns the volume's device
// buffers and point-location structure (volume_buffers.hpp) and the kernels; trace() may be
// called many times.
//
// A trace runs its lines in batches that fit the options' memory budget (and the device's buffer
// range and dispatch limits), each batch in rounds of steps (gpu_rounds.hpp) whose real points
// alone come back to the host (or stay on the device: traceOnDevice), so host and device memory
// stay within the budget whatever the number of steps; the result is that of one run. Within a
// batch, threads take the lines in Morton order of their seeds, so that a subgroup traces
// neighbouring seeds through the same bricks; results are returned in line order either way.

#include <cstddef>
#include <functional>
#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "backend.hpp"
#include "device_traces.hpp"
#include "flow/cpu_tracer.hpp"
#include "flow/line_plan.hpp"
#include "flow/round_tracer.hpp"
#include "flow/trace_set.hpp"
#include "flow/vector_volume.hpp"
#include "round_buffers.hpp"
#include "round_kernels.hpp"
#include "staging_ring.hpp"
#include "trace_kernel.hpp"
#include "volume_buffers.hpp"

namespace amrstream::gpu {

class GpuRounds;

// The work of the last trace().
struct TraceRunStats {
  std::optional<double> kernelSeconds;      // the tracing kernel, summed over rounds (with timing)
  std::optional<double> compactionSeconds;  // compaction and point data (with timing)
  std::size_t batches = 0;
  std::size_t rounds = 0;
  std::uint32_t mostLanesPerLine = 0;  // invocations a line in the widest-spread round
  std::uint64_t roundBytes = 0;        // device bytes of the largest batch's round buffers
  // Host wall time of trace()'s parts: planning the lines, making the batches' buffers, ordering
  // and uploading their lines, submitting rounds and copies, waiting for the rounds and for their
  // copies, unpacking the copies, collecting them, storing the result and assembling the lines
  // (0 for traceToRounds).
  double planSeconds = 0.0, buffersSeconds = 0.0, linesSeconds = 0.0, submitSeconds = 0.0,
         roundWaitSeconds = 0.0, copyWaitSeconds = 0.0, unpackSeconds = 0.0, collectSeconds = 0.0,
         storeSeconds = 0.0, assembleSeconds = 0.0;
  // advanceRound(): reading the live lines' states back, summed over calls.
  double statesSeconds = 0.0;
  // Lines the CPU reference finished (options.cpuTailLines), the steps it took for them, and
  // its wall time (from reading their states back).
  std::size_t tailLines = 0;
  std::uint64_t tailSteps = 0;
  double tailSeconds = 0.0;
};

// Each backend's kernel settings for a run of at most `particleSteps` steps in all: dual cells
// (KernelSettings::dualValues) only where the tracing they save pays for laying them out and
// freeing them, which takes about 0.6 s for 9 GB on an H100 (docs/performance-notes.md,
// "2026-12-07 — Dual cells only where they pay").
KernelSettings runKernelSettings(Backend backend, const flow::VectorVolume& volume,
                                 std::uint64_t particleSteps);

class GpuTracer {
 public:
  // The context must have requiredCapabilities(backend) and outlive the tracer; `volume` must
  // outlive it too.
  GpuTracer(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume);
  GpuTracer(const vk::Context& ctx, Backend backend, const flow::VectorVolume& volume,
            const KernelSettings& settings);

  // Seeds in physical coordinates, as flow::traceStreamlines, with the same result layout.
  flow::TraceSet trace(std::span<const glm::dvec3> seeds, const flow::TraceOptions& options,
                       const flow::TraceProgress& progress = {});
  // The same, the points left in the rounds that made them (see flow::traceToRounds).
  flow::StoredTraces traceToRounds(std::span<const glm::dvec3> seeds,
                                   const flow::TraceOptions& options,
                                   const flow::TraceProgress& progress = {});

  // The same, the points left on the device in the rounds that made them (see DeviceTraces; the
  // tracer must outlive them),
  // or nothing when there are no lines or they might not fit: with history, every line's
  // maxSteps + 1 points must fit within 80 % of the device memory left after the round buffers'
  // budget.
  std::unique_ptr<DeviceTraces> traceOnDevice(std::span<const glm::dvec3> seeds,
                                              const flow::TraceOptions& options,
                                              const flow::TraceProgress& progress = {});
  // Whether traceOnDevice() would keep these lines' points: see there.
  bool fitsOnDevice(const flow::TraceOptions& options, std::size_t lines) const;

  // Lines (flow::planLines) that advance one round per call, for progressive tracing; all in
  // one batch, with room for rounds of up to `mostRoundSteps` steps (at least what the memory
  // budget gives). Throws InputError naming steps_per_frame when such a round's points cannot
  // fit one device buffer. The tracer must outlive the result.
  std::unique_ptr<flow::RoundTracer> startRounds(std::span<const shared::LineState> lines,
                                                 const flow::TraceOptions& options,
                                                 std::uint32_t mostRoundSteps);

  // One round of at most `steps` steps for `lines` (states of any earlier rounds, in any order),
  // in the tracer's kept buffers: the round's block, and `lines` left holding the live lines'
  // states. For MPI ranks that hand lines to each other between rounds. Adds its work to
  // lastRun().
  // With `order`, the lines are first put in the tracer's thread order (Morton, when spatial);
  // the lines coming back keep the order they went in (less those that ended).
  flow::RoundBlock advanceRound(std::vector<shared::LineState>& lines,
                                const flow::TraceOptions& options, std::uint32_t steps, bool order);

  // The backend's locateRegion() for points in finest-cell units: the region id, or -1 outside
  // the domain and in empty space. Used by tests to compare point location with brute force.
  std::vector<std::int32_t> locate(std::span<const glm::vec3> cellPoints);

  // Waits for the device, then hands over the volume's device buffers for the caller to free
  // (on another thread, say): traces kept on the device stay readable, but the tracer traces and
  // locates no more (std::logic_error).
  VolumeBuffers releaseVolume();

  Backend backend() const { return kernel_.backend; }
  const TracerSetup& setup() const { return setup_; }
  // The kernels' settings, as the volume allowed them (dual values only where it holds them).
  const KernelSettings& settings() const { return settings_; }
  const VolumeBuffers& volumeBuffers() const { return device_; }
  const TraceRunStats& lastRun() const { return lastRun_; }
  // Lines one batch of trace() holds for these options.
  std::size_t linesPerBatch(const flow::TraceOptions& options, std::size_t lines) const;
  // Output slots for a batch: the budget's, within the device's buffer range.
  std::uint64_t pointSlots(const flow::TraceOptions& options, std::size_t batchLines) const;
  // Caps the lines per batch (0: no cap), so that tests can run many batches on small inputs.
  void limitLinesPerBatch(std::size_t limit) { batchLimit_ = limit; }
  // Whether threads take lines in Morton order of their positions (on by default).
  void orderSeedsSpatially(bool on) { spatialOrder_ = on; }
  // Timestamps around each round's kernels (off by default: they may keep the device from
  // overlapping a round with the copy of the one before).
  void timeKernels(bool on) { timeKernels_ = on; }
  // The bytes of one column that traceOnDevice()'s traces copy out at a time (tests use a few
  // points).
  void setTraceWindow(std::uint64_t bytes) { traceWindow_ = bytes; }
  // Replaces the staging ring the points come back through (tests use slots of a few points).
  void setStaging(std::size_t slots, std::uint64_t slotBytes);

 private:
  // Throws std::logic_error once releaseVolume() has run.
  void requireVolume() const;
  // Runs each kernel once on no lines (GpuRounds::compileByDispatch).
  void compileByDispatch();
  // What a round costs, and the automatic budget's bounds on this device.
  flow::RoundCosts roundCosts(const flow::TraceOptions& options) const;
  // The lines of a trace of `seeds`; resets lastRun() and times the planning.
  flow::LinePlan planRun(std::span<const glm::dvec3> seeds, const flow::TraceOptions& options);
  // Traces `states` batch by batch; `run` runs a batch's rounds to the end with the steps per
  // round it is given.
  using StepsFor = std::function<std::uint32_t(std::size_t live)>;
  // Finishes `lines` (live states of GPU rounds) with the CPU reference, handing its rounds to
  // `consume`; `lineEnded` is called from the worker threads as lines end.
  void finishOnCpu(std::span<const shared::LineState> lines, const flow::TraceOptions& options,
                   const std::function<void(flow::RoundBlock&&)>& consume,
                   const std::function<void()>& lineEnded);
  void traceBatches(std::span<const shared::LineState> states, const flow::TraceOptions& options,
                    const std::function<void(GpuRounds&, const StepsFor&)>& run);
  // Invocations one dispatch of the tracing kernel may have (lines per batch, and spreads).
  std::uint64_t mostInvocations() const;
  // The kernel taking the options' integrator's steps.
  const TraceKernel& kernelFor(const flow::TraceOptions& options);

  const vk::Context* ctx_;
  const flow::VectorVolume* volume_;
  TracerSetup setup_;
  std::unique_ptr<StagingRing> staging_;  // made while the volume and kernels are
  VolumeBuffers device_;
  TraceKernel kernel_;  // with settings_.integrator
  KernelSettings settings_;
  std::map<flow::Integrator, TraceKernel> otherKernels_;  // created by the first trace needing one
  RoundKernels roundKernels_;
  GatherKernel gatherKernel_;                   // for traceOnDevice()'s traces
  std::optional<TraceKernel> probe_;            // created by the first locate()
  std::unique_ptr<RoundBuffers> roundBuffers_;  // kept for the next batch or trace that fits
  std::size_t batchLimit_ = 0;
  bool spatialOrder_ = true;
  bool timeKernels_ = false;
  std::uint64_t traceWindow_ = DeviceTraces::kWindowBytes;
  TraceRunStats lastRun_;
  bool volumeReleased_ = false;
};

}  // namespace amrstream::gpu
