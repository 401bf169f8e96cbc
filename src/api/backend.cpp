#include "tracer_choice.hpp"

#include <fmt/format.h>
#include <tbb/info.h>

#include <algorithm>
#include <cctype>

#include "gpu/backend.hpp"
#include "gpu/gpu_tracer.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"
#include "vk/context.hpp"
#include "vk/context_error.hpp"
#include "vk/device_report.hpp"

namespace amrstream::cli {

namespace {

bool nameMatches(const std::string& name, const std::string& filter) {
  const auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
  };
  return lower(name).find(lower(filter)) != std::string::npos;
}

// The device `auto` uses: the requested one, else the first discrete GPU with a GPU backend,
// else the first device with one.
const vk::DeviceReport* autoDevice(const std::vector<vk::DeviceReport>& devices,
                                   const std::string& filter) {
  const vk::CapabilitySet compute = gpu::requiredCapabilities(gpu::Backend::Compute);
  const vk::DeviceReport* best = nullptr;
  for (const vk::DeviceReport& d : devices) {
    if (!filter.empty() && !nameMatches(d.name, filter)) continue;
    if (!d.supports(compute)) continue;
    if (d.type == VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU) return &d;
    if (!best) best = &d;
  }
  return best;
}

}  // namespace

BackendChoice chooseBackend(const BackendRequest& request, BackendUse use) {
  BackendChoice choice{gpu::Backend::Cpu, request.device};
  if (request.backend == "auto") {
    std::vector<vk::DeviceReport> devices;
    try {
      devices = vk::listDevices();
    } catch (const vk::ContextError& e) {
      fmt::print("backend    cpu: no Vulkan ({})\n", e.what());
    }
    std::string why;
    const vk::DeviceReport* device = autoDevice(devices, request.device);
    if (use == BackendUse::Trace && request.device.empty() && device &&
        device->type == VK_PHYSICAL_DEVICE_TYPE_CPU) {
      fmt::print(
          "backend    auto: cpu ({} is a software Vulkan device, slower than the CPU "
          "reference; name --backend rayquery, pipeline or compute to trace on it)\n",
          device->name);
      return choice;
    }
    choice.backend = gpu::chooseBackend(device, why);
    if (device) choice.deviceFilter = device->name;
    fmt::print("backend    auto: {}\n", why);
  } else {
    choice.backend = *gpu::parseBackend(request.backend);
  }
  return choice;
}

vk::Context createContext(const BackendRequest& request, const BackendChoice& choice,
                          vk::CapabilitySet extra) {
  vk::ContextBuilder builder;
  builder.require(gpu::requiredCapabilities(choice.backend))
      .require(extra)
      .validation(request.validation);
  if (!choice.deviceFilter.empty()) builder.deviceName(choice.deviceFilter);
  return builder.build();
}

void checkValidation(const vk::Context& ctx) {
  if (ctx.validationErrorCount() > 0)
    throw std::runtime_error(
        fmt::format("the Vulkan validation layer reported {} errors", ctx.validationErrorCount()));
}

flow::StoredTraces traceWithBackend(const BackendRequest& request, flow::VectorVolume& volume,
                                    std::span<const glm::dvec3> seeds,
                                    const flow::TraceOptions& options,
                                    const flow::TraceProgress& progress, TraceReport* report,
                                    HostValues hostValues) {
  TraceReport local;
  TraceReport& t = report ? *report : local;
  const BackendChoice choice = chooseBackend(request, BackendUse::Trace);
  const gpu::Backend backend = choice.backend;
  Stopwatch clock;
  if (backend == gpu::Backend::Cpu) {
    fmt::print("tracing    on the CPU reference ({} threads)\n", tbb::info::default_concurrency());
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
  }
  t.setupSeconds = clock.seconds();
  t.backend = gpu::backendName(backend);
  t.device = ctx.deviceName();
  fmt::print(
      "tracing    backend {} on {} [device setup {:.2f} s: upload {:.2f} s, structure "
      "{:.2f} s, kernels {:.2f} s]\n",
      gpu::backendName(backend), ctx.deviceName(), t.setupSeconds, tracer.setup().uploadSeconds,
      tracer.setup().structureSeconds, tracer.setup().pipelineSeconds);
  clock.restart();
  flow::StoredTraces traces = tracer.traceToRounds(seeds, options, progress);
  t.traceSeconds = clock.seconds();
  checkValidation(ctx);
  const gpu::TraceRunStats& run = tracer.lastRun();
  fmt::print(
      "rounds     {} in {} batch{}: plan {:.3f} s, buffers {:.3f} s, lines {:.3f} s, submitting "
      "{:.3f} s, "
      "waiting for rounds {:.3f} s and copies {:.3f} s, unpacking {:.3f} s, collecting "
      "{:.3f} s, storing {:.3f} s\n",
      run.rounds, run.batches, run.batches == 1 ? "" : "es", run.planSeconds, run.buffersSeconds,
      run.linesSeconds, run.submitSeconds, run.roundWaitSeconds, run.copyWaitSeconds,
      run.unpackSeconds, run.collectSeconds, run.storeSeconds);
  return traces;
}

}  // namespace amrstream::cli
