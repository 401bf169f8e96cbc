#include "api/held_traces.hpp"

#include <fmt/format.h>

#include <memory>
#include <thread>

#include "api/device.hpp"
#include "api/trace_memory.hpp"
#include "flow/cpu_tracer.hpp"
#include "gpu/gpu_tracer.hpp"
#include "util/host_threads.hpp"
#include "util/stopwatch.hpp"
#include "vk/vk_error.hpp"

namespace amrstream {

namespace {

// A GPU backend's device, open with the volume on it.
struct GpuSession {
  GpuSession(vk::Context context, gpu::Backend backend, flow::VectorVolume& volume,
             std::uint64_t particleSteps)
      : ctx(std::move(context)),
        tracer(ctx, backend, volume, gpu::runKernelSettings(backend, volume, particleSteps)) {}
  // Writing reads the kept points alone: the driver takes the volume's device memory back
  // (a quarter of a second for a large one) on a thread of its own meanwhile.
  void releaseVolumeInBackground() {
    volumeRelease = std::jthread([volume = std::make_unique<gpu::VolumeBuffers>(
                                      tracer.releaseVolume())]() mutable { volume.reset(); });
  }

  vk::Context ctx;
  gpu::GpuTracer tracer;
  std::jthread volumeRelease;  // declared last: joined before the tracer and the device go
};

// The CPU finishes the last lines of a trace with options.cpuTailLines from the host's values.
HostValues hostValuesFor(const flow::TraceOptions& options, HostValues asked) {
  return options.cpuTailLines > 0 ? HostValues::Keep : asked;
}

// The most steps the seeds' lines can take in all.
std::uint64_t mostParticleSteps(std::size_t seeds, const flow::TraceOptions& options) {
  const std::uint64_t lines = options.direction == flow::Direction::Both ? 2 * seeds : seeds;
  return lines * options.maxSteps;
}

// Opens the device for a GPU backend and uploads the volume for tracing `seeds`, saying so on
// `log`.
std::unique_ptr<GpuSession> openDevice(const BackendRequest& request, const BackendChoice& choice,
                                       flow::VectorVolume& volume, std::size_t seeds,
                                       const flow::TraceOptions& options, TraceReport& t,
                                       HostValues hostValues, const Log& log,
                                       std::optional<vk::Context> opened = std::nullopt,
                                       double openedWait = 0.0) {
  Stopwatch clock;
  auto session =
      std::make_unique<GpuSession>(opened ? std::move(*opened) : createContext(request, choice),
                                   choice.backend, volume, mostParticleSteps(seeds, options));
  if (hostValues == HostValues::Release) {
    decltype(volume.values)().swap(volume.values);
    decltype(volume.channelValues)().swap(volume.channelValues);
    decltype(volume.cellIds)().swap(volume.cellIds);
    decltype(volume.vectorGradients)().swap(volume.vectorGradients);
    decltype(volume.channelGradients)().swap(volume.channelGradients);
  }
  t.setupSeconds = openedWait + clock.seconds();
  t.backend = gpu::backendName(choice.backend);
  t.device = session->ctx.deviceName();
  const gpu::TracerSetup& setup = session->tracer.setup();
  t.uploadSeconds = setup.uploadSeconds;
  t.structureSeconds = setup.structureSeconds;
  t.kernelSeconds = setup.pipelineSeconds;
  t.dualCells = session->tracer.settings().dualValues.value_or(false);
  say(log, fmt::format("tracing    backend {} on {} [device setup {:.2f} s: upload {:.2f} s{}, "
                       "structure {:.2f} s, kernels {:.2f} s]",
                       t.backend, t.device, t.setupSeconds, setup.uploadSeconds,
                       t.dualCells ? " with dual cells" : "", setup.structureSeconds,
                       setup.pipelineSeconds));
  return session;
}

// Where a GPU trace's host time went.
void sayRounds(const gpu::TraceRunStats& run, const Log& log) {
  say(log,
      fmt::format("rounds     {} in {} batch{}: plan {:.3f} s, buffers {:.3f} s, lines {:.3f} s, "
                  "submitting "
                  "{:.3f} s, waiting for rounds {:.3f} s and copies {:.3f} s, unpacking {:.3f} s, "
                  "collecting {:.3f} s, storing {:.3f} s",
                  run.rounds, run.batches, run.batches == 1 ? "" : "es", run.planSeconds,
                  run.buffersSeconds, run.linesSeconds, run.submitSeconds, run.roundWaitSeconds,
                  run.copyWaitSeconds, run.unpackSeconds, run.collectSeconds, run.storeSeconds));
  if (run.tailLines > 0)
    say(log,
        fmt::format("cpu tail   {} line{} finished on the CPU: {} steps in {:.3f} s", run.tailLines,
                    run.tailLines == 1 ? "" : "s", run.tailSteps, run.tailSeconds));
}

flow::StoredTraces traceOnTheCpu(flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
                                 const flow::TraceOptions& options,
                                 const flow::TraceProgress& progress, TraceReport& t,
                                 const Log& log) {
  say(log, "tracing    on the CPU reference (" + hostThreadsText() + ")");
  t.backend = "cpu";
  t.device = hostThreadsText();
  Stopwatch clock;
  flow::StoredTraces traces = flow::traceToRounds(volume, seeds, options, progress);
  t.traceSeconds = clock.seconds();
  return traces;
}

flow::StoredTraces traceOnHost(gpu::GpuTracer& tracer, const vk::Context& ctx,
                               std::span<const glm::dvec3> seeds, const flow::TraceOptions& options,
                               const flow::TraceProgress& progress, TraceReport& t,
                               const Log& log) {
  Stopwatch clock;
  flow::StoredTraces traces = tracer.traceToRounds(seeds, options, progress);
  t.traceSeconds = clock.seconds();
  checkValidation(ctx);
  sayRounds(tracer.lastRun(), log);
  return traces;
}

class HostTraces final : public HeldTraces {
 public:
  explicit HostTraces(flow::StoredTraces traces) : traces_(std::move(traces)) {}
  const flow::TraceView& view() const override { return traces_; }
  flow::TraceSet assemble() && override { return std::move(traces_).assemble(); }

 private:
  flow::StoredTraces traces_;
};

class TracesOnDevice final : public HeldTraces {
 public:
  TracesOnDevice(std::unique_ptr<GpuSession> session, std::unique_ptr<gpu::DeviceTraces> traces)
      : session_(std::move(session)), traces_(std::move(traces)) {}
  const flow::TraceView& view() const override { return *traces_; }
  flow::TraceSet assemble() && override {
    throw std::logic_error("traces kept on the device are read through their view");
  }

 private:
  std::unique_ptr<GpuSession> session_;
  std::unique_ptr<gpu::DeviceTraces> traces_;  // declared last: freed before the device
};

}  // namespace

flow::StoredTraces traceSeeds(const BackendRequest& request, flow::VectorVolume& volume,
                              std::span<const glm::dvec3> seeds, const flow::TraceOptions& options,
                              const flow::TraceProgress& progress, TraceReport* report,
                              HostValues hostValues, const Log& log) {
  TraceReport local;
  TraceReport& t = report ? *report : local;
  Stopwatch choosing;
  const BackendChoice choice = chooseBackend(request, BackendUse::Trace, log);
  t.chooseSeconds = choosing.seconds();
  checkHostTracesFit(volume, seeds, options);
  if (choice.backend == gpu::Backend::Cpu)
    return traceOnTheCpu(volume, seeds, options, progress, t, log);
  const std::unique_ptr<GpuSession> session = openDevice(
      request, choice, volume, seeds.size(), options, t, hostValuesFor(options, hostValues), log);
  return traceOnHost(session->tracer, session->ctx, seeds, options, progress, t, log);
}

std::unique_ptr<HeldTraces> traceForWriting(
    const BackendRequest& request, flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
    const flow::TraceOptions& options, TraceStore store, const flow::TraceProgress& progress,
    TraceReport* report, HostValues hostValues, const Log& log, DeviceOpening* opening) {
  TraceReport local;
  TraceReport& t = report ? *report : local;
  // The wait for a device opened meanwhile is the device setup's.
  Stopwatch waiting;
  std::optional<DeviceOpening::Opened> opened;
  if (opening) opened = opening->take(log);
  const double openedWait = waiting.seconds();
  Stopwatch choosing;
  const BackendChoice choice =
      opened ? opened->choice : chooseBackend(request, BackendUse::Trace, log);
  t.chooseSeconds = choosing.seconds();
  // Before the device may free the volume's host values, which the check's sample reads.
  checkHostTracesFit(volume, seeds, options);
  if (choice.backend == gpu::Backend::Cpu) {
    t.chooseSeconds += openedWait;
    return std::make_unique<HostTraces>(traceOnTheCpu(volume, seeds, options, progress, t, log));
  }
  std::unique_ptr<GpuSession> session = openDevice(
      request, choice, volume, seeds.size(), options, t, hostValuesFor(options, hostValues), log,
      opened ? std::move(opened->ctx) : std::nullopt, openedWait);
  const bool software = session->ctx.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const bool deviceStore = store == TraceStore::Device || (store == TraceStore::Auto && !software);
  if (deviceStore && options.cpuTailLines > 0)
    say(log, "points     to host memory: the CPU finishes the last lines ({cpu_tail})");
  else if (deviceStore) {
    Stopwatch clock;
    std::unique_ptr<gpu::DeviceTraces> kept;
    try {
      kept = session->tracer.traceOnDevice(seeds, options, progress);
      if (!kept) say(log, "points     to host memory: they might not fit in the device's");
    } catch (const vk::VulkanError& e) {
      // Room is made for every point a round might emit: it may run out where the points fit.
      if (e.result() != VK_ERROR_OUT_OF_DEVICE_MEMORY) throw;
      say(log, fmt::format("points     the device's memory ran out ({}): tracing again into "
                           "host memory",
                           e.what()));
    }
    if (kept) {
      t.traceSeconds = clock.seconds();
      checkValidation(session->ctx);
      sayRounds(session->tracer.lastRun(), log);
      say(log, fmt::format("points     kept on the device ({:.2f} GiB), copied out as written",
                           double(kept->deviceBytes()) / 0x1p30));
      session->releaseVolumeInBackground();
      return std::make_unique<TracesOnDevice>(std::move(session), std::move(kept));
    }
  }
  return std::make_unique<HostTraces>(
      traceOnHost(session->tracer, session->ctx, seeds, options, progress, t, log));
}

}  // namespace amrstream
