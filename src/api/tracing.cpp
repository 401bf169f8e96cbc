#include "amrstream/tracing.hpp"

#include <fmt/format.h>
#include <tbb/info.h>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "gpu/gpu_tracer.hpp"
#include "util/stopwatch.hpp"

namespace amrstream {

const char* reasonName(int reason) {
  switch (reason) {
    case AMRSTREAM_REASON_OUT_OF_DOMAIN:
      return "out of domain";
    case AMRSTREAM_REASON_UNEXPECTED_VALUE:
      return "invalid sample";
    case AMRSTREAM_REASON_MAX_LENGTH:
      return "max length";
    case AMRSTREAM_REASON_MAX_STEPS:
      return "max steps";
    case AMRSTREAM_REASON_STAGNATION:
      return "stagnation";
    case AMRSTREAM_REASON_MAX_TIME:
      return "max time";
    case AMRSTREAM_REASON_PERIODIC_WRAP:
      return "periodic wrap";
    case AMRSTREAM_REASON_SERIES_END:
      return "end of series";
    default:
      return "unknown";
  }
}

flow::StoredTraces trace(const BackendRequest& request, flow::VectorVolume& volume,
                         std::span<const glm::dvec3> seeds, const flow::TraceOptions& options,
                         const flow::TraceProgress& progress, TraceReport* report,
                         HostValues hostValues, const Log& log) {
  TraceReport local;
  TraceReport& t = report ? *report : local;
  const BackendChoice choice = chooseBackend(request, BackendUse::Trace, log);
  const gpu::Backend backend = choice.backend;
  Stopwatch clock;
  if (backend == gpu::Backend::Cpu) {
    say(log, fmt::format("tracing    on the CPU reference ({} threads)",
                         tbb::info::default_concurrency()));
    t.backend = "cpu";
    t.device = fmt::format("{} threads", tbb::info::default_concurrency());
    flow::StoredTraces traces = flow::traceToRounds(volume, seeds, options, progress);
    t.traceSeconds = clock.seconds();
    return traces;
  }
  const vk::Context ctx = createContext(request, choice);
  gpu::GpuTracer tracer(ctx, backend, volume);
  if (hostValues == HostValues::Release) {
    decltype(volume.values)().swap(volume.values);
    decltype(volume.channelValues)().swap(volume.channelValues);
    decltype(volume.cellIds)().swap(volume.cellIds);
    decltype(volume.vectorGradients)().swap(volume.vectorGradients);
    decltype(volume.channelGradients)().swap(volume.channelGradients);
  }
  t.setupSeconds = clock.seconds();
  t.backend = gpu::backendName(backend);
  t.device = ctx.deviceName();
  say(log,
      fmt::format("tracing    backend {} on {} [device setup {:.2f} s: upload {:.2f} s, structure "
                  "{:.2f} s, kernels {:.2f} s]",
                  gpu::backendName(backend), ctx.deviceName(), t.setupSeconds,
                  tracer.setup().uploadSeconds, tracer.setup().structureSeconds,
                  tracer.setup().pipelineSeconds));
  clock.restart();
  flow::StoredTraces traces = tracer.traceToRounds(seeds, options, progress);
  t.traceSeconds = clock.seconds();
  checkValidation(ctx);
  const gpu::TraceRunStats& run = tracer.lastRun();
  say(log,
      fmt::format("rounds     {} in {} batch{}: plan {:.3f} s, buffers {:.3f} s, lines {:.3f} s, "
                  "submitting "
                  "{:.3f} s, waiting for rounds {:.3f} s and copies {:.3f} s, unpacking {:.3f} s, "
                  "collecting {:.3f} s, storing {:.3f} s",
                  run.rounds, run.batches, run.batches == 1 ? "" : "es", run.planSeconds,
                  run.buffersSeconds, run.linesSeconds, run.submitSeconds, run.roundWaitSeconds,
                  run.copyWaitSeconds, run.unpackSeconds, run.collectSeconds, run.storeSeconds));
  return traces;
}

}  // namespace amrstream
