#include "bench_runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <set>
#include <stdexcept>

#include "gpu/backend.hpp"
#include "gpu/gpu_tracer.hpp"
#include "util/host_threads.hpp"
#include "util/stopwatch.hpp"
#include "vk/context.hpp"
#include "vk/context_error.hpp"

namespace amrstream::bench {

namespace {

std::uint64_t totalSteps(const flow::TraceSet& traces) {
  return std::accumulate(traces.steps.begin(), traces.steps.end(), std::uint64_t(0));
}

BenchRow measuredRow(const std::string& backend, const std::string& device, bool history,
                     std::size_t particles, const flow::TraceSet& traces, const BenchConfig& config,
                     double wallSeconds) {
  BenchRow row;
  row.backend = backend;
  row.device = device;
  row.history = history;
  row.particles = particles;
  row.maxSteps = config.trace.maxSteps;
  row.steps = totalSteps(traces);
  row.wallSeconds = wallSeconds;
  return row;
}

// Keeps the faster of two measurements of the same row.
void keepFaster(std::optional<BenchRow>& best, const BenchRow& row) {
  if (!best || row.stepsPerSecond() > best->stepsPerSecond()) best = row;
}

// Decides which rows run; the first row skipped for each reason gets a note saying why.
class RowPlanner {
 public:
  RowPlanner(const BenchConfig& config, const BenchCallbacks& callbacks, BenchReport& report)
      : config_(config), callbacks_(callbacks), report_(report) {}

  bool runs(const std::string& backend, bool history, std::size_t particles) {
    if (backend == "cpu" && particles > config_.cpuMaxParticles)
      return skip("cpu", fmt::format("cpu skips counts above {{cpu_max_particles}} {}",
                                     config_.cpuMaxParticles));
    const std::uint64_t points = std::uint64_t(particles) * (config_.trace.maxSteps + 1);
    if (history && points > config_.historyPointBudget)
      return skip("history " + backend,
                  fmt::format("{} skips history rows from {} particles: {} points exceed "
                              "{{history_points}} {}",
                              backend, particles, points, config_.historyPointBudget));
    return true;
  }

 private:
  bool skip(const std::string& reason, const std::string& why) {
    if (noted_.insert(reason).second) {
      report_.notes.push_back(why);
      if (callbacks_.note) callbacks_.note(why);
    }
    return false;
  }

  const BenchConfig& config_;
  const BenchCallbacks& callbacks_;
  BenchReport& report_;
  std::set<std::string> noted_;
};

// A row's seeds on this rank: all of the first n without a share.
std::vector<glm::dvec3> rowSeeds(std::span<const glm::dvec3> seeds, std::size_t n,
                                 const BenchCallbacks& callbacks) {
  const std::span<const glm::dvec3> row = seeds.first(n);
  if (!callbacks.share) return {row.begin(), row.end()};
  std::vector<glm::dvec3> mine;
  for (const std::uint32_t i : callbacks.share->indicesOf(row)) mine.push_back(row[i]);
  return mine;
}

void startTogether(const BenchCallbacks& callbacks) {
  if (callbacks.share) callbacks.share->synchronize();
}

// The row as all ranks measured it.
BenchRow combined(BenchRow row, const BenchCallbacks& callbacks) {
  if (!callbacks.share) return row;
  const RankShare& share = *callbacks.share;
  // Every rank joins every sum and maximum, also a rank whose share of the row is empty and so
  // has no kernel time (-1 stands for none).
  const auto slowest = [&](std::optional<double> seconds) -> std::optional<double> {
    const double most = share.maxOf(seconds.value_or(-1.0));
    return most < 0.0 ? std::nullopt : std::optional(most);
  };
  row.steps = std::uint64_t(share.sumOf(double(row.steps)));
  row.wallSeconds = share.maxOf(row.wallSeconds);
  row.kernelSeconds = slowest(row.kernelSeconds);
  row.compactionSeconds = slowest(row.compactionSeconds);
  row.deviceBytes = std::uint64_t(share.maxOf(double(row.deviceBytes)));
  row.chunks = std::size_t(share.maxOf(double(row.chunks)));
  row.rounds = std::size_t(share.maxOf(double(row.rounds)));
  return row;
}

flow::TraceOptions optionsFor(const BenchConfig& config, bool history) {
  flow::TraceOptions options = config.trace;
  options.keepHistory = history;
  return options;
}

void runCpu(const flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
            const BenchConfig& config, BenchReport& report, const BenchCallbacks& callbacks,
            RowPlanner& planner) {
  const std::string device = hostDescription();
  for (const bool history : config.historyModes) {
    for (const std::size_t n : config.particles) {
      if (!planner.runs("cpu", history, n)) continue;
      const std::vector<glm::dvec3> mine = rowSeeds(seeds, n, callbacks);
      std::optional<BenchRow> best;
      for (std::uint32_t r = 0; r < config.repeats; ++r) {
        startTogether(callbacks);
        Stopwatch clock;
        const flow::StoredTraces stored =
            flow::traceToRounds(volume, mine, optionsFor(config, history));
        const flow::TraceSet& traces = stored.lines();
        keepFaster(best,
                   combined(measuredRow("cpu", device, history, n, traces, config, clock.seconds()),
                            callbacks));
      }
      report.rows.push_back(*best);
      if (callbacks.rowDone) callbacks.rowDone(*best);
    }
  }
}

void runGpu(gpu::Backend backend, const flow::VectorVolume& volume,
            std::span<const glm::dvec3> seeds, const BenchConfig& config, BenchReport& report,
            const BenchCallbacks& callbacks, RowPlanner& planner) {
  const std::string name(gpu::backendName(backend));
  Stopwatch clock;
  vk::ContextBuilder builder;
  builder.require(gpu::requiredCapabilities(backend)).validation(config.validation);
  if (!config.deviceFilter.empty()) builder.deviceName(config.deviceFilter);
  builder.deviceSlot(config.deviceSlot);
  std::optional<vk::Context> ctx;
  try {
    ctx.emplace(builder.build());
  } catch (const vk::ContextError& e) {
    const std::string why = fmt::format("{} not run: {}", name, e.what());
    report.notes.push_back(why);
    if (callbacks.note) callbacks.note(why);
    return;
  }
  BackendSetup setup{name, ctx->deviceName(),
                     fmt::format("{} {}", ctx->report().driverName, ctx->report().driverInfo)};
  setup.contextSeconds = clock.seconds();
  gpu::KernelSettings settings = gpu::defaultKernelSettings(backend);
  if (config.regionHint) settings.useRegionHint = *config.regionHint;
  if (config.dualValues) settings.dualValues = *config.dualValues;
  if (config.spreadThreads) settings.spreadThreads = *config.spreadThreads;
  gpu::GpuTracer tracer(*ctx, backend, volume, settings);
  tracer.orderSeedsSpatially(config.spatialSeedOrder);
  tracer.timeKernels(true);
  setup.regionHint = settings.useRegionHint;
  setup.dualValues = tracer.settings().dualValues.value_or(false);
  setup.spreadThreads = tracer.settings().spreadThreads.value_or(0);
  setup.uploadSeconds = tracer.setup().uploadSeconds;
  setup.structureSeconds = tracer.setup().structureSeconds;
  setup.pipelineSeconds = tracer.setup().pipelineSeconds;
  setup.volumeBytes = tracer.setup().volumeBytes;
  setup.structureBytes = tracer.setup().structureBytes;
  report.setups.push_back(setup);
  if (callbacks.setupDone) callbacks.setupDone(setup);

  flow::TraceOptions warmUp = optionsFor(config, false);
  warmUp.maxSteps = std::min<std::uint32_t>(warmUp.maxSteps, 10);
  tracer.trace(seeds.first(std::min<std::size_t>(seeds.size(), 1024)), warmUp);

  for (const bool history : config.historyModes) {
    for (const std::size_t n : config.particles) {
      if (!planner.runs(name, history, n)) continue;
      const std::vector<glm::dvec3> mine = rowSeeds(seeds, n, callbacks);
      std::optional<BenchRow> best;
      for (std::uint32_t r = 0; r < config.repeats; ++r) {
        startTogether(callbacks);
        clock.restart();
        const flow::StoredTraces stored = tracer.traceToRounds(mine, optionsFor(config, history));
        const flow::TraceSet& traces = stored.lines();
        BenchRow row = measuredRow(name, setup.device, history, n, traces, config, clock.seconds());
        row.kernelSeconds = tracer.lastRun().kernelSeconds;
        row.compactionSeconds = tracer.lastRun().compactionSeconds;
        row.chunks = tracer.lastRun().batches;
        row.rounds = tracer.lastRun().rounds;
        row.tailLines = tracer.lastRun().tailLines;
        row.tailSteps = tracer.lastRun().tailSteps;
        row.tailSeconds = tracer.lastRun().tailSeconds;
        row.deviceBytes = setup.volumeBytes + setup.structureBytes + tracer.lastRun().roundBytes;
        keepFaster(best, combined(row, callbacks));
      }
      report.rows.push_back(*best);
      if (callbacks.rowDone) callbacks.rowDone(*best);
    }
  }
  if (ctx->validationErrorCount() > 0)
    throw std::runtime_error(fmt::format("the Vulkan validation layer reported {} errors on {}",
                                         ctx->validationErrorCount(), name));
}

// A GPU row whose step total differs from the CPU reference's for the same particles and mode by
// more than a few boundary cases (float division differs in the last ulp) gets a note.
void compareWithCpu(BenchReport& report, const BenchCallbacks& callbacks) {
  for (const BenchRow& row : report.rows) {
    if (row.backend == "cpu") continue;
    for (const BenchRow& cpu : report.rows) {
      if (cpu.backend != "cpu" || cpu.particles != row.particles || cpu.history != row.history)
        continue;
      const double difference = std::abs(double(row.steps) - double(cpu.steps));
      if (difference <= std::max(2.0, 1e-5 * double(cpu.steps))) continue;
      const std::string why =
          fmt::format("{} with {} particles took {} steps, the cpu {}: the results differ",
                      row.backend, row.particles, row.steps, cpu.steps);
      report.notes.push_back(why);
      if (callbacks.note) callbacks.note(why);
    }
  }
}

}  // namespace

double BenchRow::stepsPerSecond() const {
  const double seconds = kernelSeconds && tailLines == 0 ? *kernelSeconds : wallSeconds;
  return double(steps) / std::max(seconds, 1e-12);
}

double BenchRow::wallStepsPerSecond() const { return double(steps) / std::max(wallSeconds, 1e-12); }

void runBenchmark(const flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
                  const BenchConfig& config, BenchReport& report, const BenchCallbacks& callbacks) {
  if (config.particles.empty()) throw std::invalid_argument("bench: no particle counts");
  if (seeds.size() < *std::max_element(config.particles.begin(), config.particles.end()))
    throw std::invalid_argument("bench: fewer seeds than the largest particle count");
  RowPlanner planner(config, callbacks, report);
  for (const std::string& name : config.backends) {
    const std::optional<gpu::Backend> backend = gpu::parseBackend(name);
    if (!backend) throw std::invalid_argument(fmt::format("bench: unknown backend '{}'", name));
    if (*backend == gpu::Backend::Cpu)
      runCpu(volume, seeds, config, report, callbacks, planner);
    else
      runGpu(*backend, volume, seeds, config, report, callbacks, planner);
  }
  compareWithCpu(report, callbacks);
}

std::string hostDescription() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return fmt::format("{}, {}", model, hostThreadsText());
}

}  // namespace amrstream::bench
