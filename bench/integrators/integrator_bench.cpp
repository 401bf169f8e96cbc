// The cost of each integrator at equal accuracy, the fair comparison of a fixed step with an
// adaptive one:
//
//   amrstream_integrator_bench [--dataset abc|rotation] [--backend B] [--seeds N]
//                              [--target-cells C] [--duration T]
//
// abc (default): the ABC flow on nested levels (builtin:abc), tent interpolant; the reference end
// points come from rk45 at a tolerance of 1e-8 cell widths per step (tiny fixed steps would
// gather float rounding over their many steps instead). rotation:
// solid-body rotation (builtin:rotation) with the linear interpolant, which reproduces a linear
// field exactly across level jumps, so the exact paths are circles in closed form. N random
// seeds, traced forward in time mode for the duration T (--max-time, the last step shortened to
// land on it), endpoints only. Steps are multiples of tau, the default time step (a quarter of
// the finest cell crossed at the maximum speed). For each integrator and step (rk45: tolerance)
// the table gives the steps taken, the error of the end points (RMS and maximum, in finest
// cells) and the tracing time (GPU backends: the kernels' time from timestamps; the CPU: wall
// time); then, for target RMS errors, the fastest run of each integrator that meets them (the
// maximum is left to a few seeds near the flow's separatrices, where rounding alone grows). A
// benchmark, not a test: nothing is asserted.

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "amrstream/backend.hpp"
#include "amrstream/dataset.hpp"
#include "amrstream/field.hpp"
#include "amrstream/trace_settings.hpp"
#include "api/device.hpp"
#include "api/handles.hpp"
#include "api/stepping.hpp"
#include "flow/cpu_tracer.hpp"
#include "gpu/gpu_tracer.hpp"
#include "synth/rotation_field.hpp"

namespace {

using namespace amrstream;

struct Run {
  std::string integrator;
  double setting = 0.0;  // the step (fixed) or the tolerance (rk45)
  std::uint64_t steps = 0;
  double rmsError = 0.0, maxError = 0.0;  // finest cells
  double seconds = 0.0;
};

glm::dvec3 exactEnd(glm::dvec3 seed, double duration) {
  const glm::dvec3 c = synth::RotationField::kCentre, r = seed - c;
  const double angle = synth::RotationField::kOmega * duration;
  return c + glm::dvec3(std::cos(angle) * r.x - std::sin(angle) * r.y,
                        std::sin(angle) * r.x + std::cos(angle) * r.y, r.z);
}

struct Runs {
  flow::VectorVolume& volume;
  const std::vector<glm::dvec3>& seeds;
  std::vector<glm::dvec3> reference;  // the end point of every seed
  float tau = 0.0f;
  double duration = 0.0;
  std::optional<vk::Context> context;  // GPU backends: one context and tracer for all runs
  std::unique_ptr<gpu::GpuTracer> tracer;
};

// Traces the seeds; returns the end points and the seconds spent tracing.
flow::TraceSet traceEnds(Runs& r, const std::string& integrator, float setting, double* seconds) {
  TraceSettings settings;
  settings.stepMode = "time";
  settings.integrator = integrator;
  settings.direction = "forward";
  settings.keepHistory = false;
  settings.maxTime = float(r.duration);
  settings.steps = 1000000;
  if (integrator == "rk45") {
    settings.tolerance = setting;
    settings.stepSize = r.tau;
    settings.minStep = r.tau / 100.0f;
    settings.maxStep = r.tau * 256.0f;
  } else {
    settings.stepSize = setting;
  }
  const flow::TraceOptions options = traceOptions(settings, r.volume);
  const auto start = std::chrono::steady_clock::now();
  flow::TraceSet traces = r.tracer ? r.tracer->trace(r.seeds, options)
                                   : flow::traceStreamlines(r.volume, r.seeds, options);
  if (seconds) {
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (r.tracer && r.tracer->lastRun().kernelSeconds)
      *seconds = *r.tracer->lastRun().kernelSeconds;
  }
  return traces;
}

Run runOnce(Runs& r, const std::string& integrator, float setting) {
  Run run{integrator, setting};
  const flow::TraceSet traces = traceEnds(r, integrator, setting, &run.seconds);
  const double finest = r.volume.transform.spacing.x;
  double sumSquares = 0.0;
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    run.steps += traces.steps[line];
    const glm::dvec3 end = glm::dvec3(traces.positions[traces.firstPoint(line)]);
    const double error = glm::length(end - r.reference[line]) / finest;
    sumSquares += error * error;
    run.maxError = std::max(run.maxError, error);
  }
  run.rmsError = std::sqrt(sumSquares / double(traces.lineCount()));
  return run;
}

}  // namespace

int main(int argc, char** argv) {
  BackendRequest request{"cpu", "", false};
  std::string dataset = "abc";
  std::size_t seedCount = 4096;
  std::size_t targetCells = 2'000'000;
  double duration = 0.1;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--backend")
      request.backend = value;
    else if (flag == "--dataset")
      dataset = value;
    else if (flag == "--seeds")
      seedCount = std::stoul(value);
    else if (flag == "--target-cells")
      targetCells = std::stoul(value);
    else if (flag == "--duration")
      duration = std::stod(value);
    else {
      fmt::print(stderr,
                 "usage: {} [--dataset abc|rotation] [--backend B] [--seeds N] "
                 "[--target-cells C] [--duration T]\n",
                 argv[0]);
      return 2;
    }
  }
  const bool rotation = dataset == "rotation";
  const Dataset cells = load("builtin:" + dataset, {6, 4, targetCells, 1});
  Field field = buildField(cells, {"", "none", "none", rotation ? "linear" : "tent"});
  flow::VectorVolume& volume = volumeOf(field);

  // Random seeds in the middle of the domain; for the rotation, within 0.05 of its refined ring.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<glm::dvec3> seeds;
  for (std::size_t i = 0; i < seedCount; ++i) {
    if (rotation) {
      const double angle = 2.0 * std::numbers::pi * unit(rng);
      const double radius = 0.2 + 0.1 * unit(rng), z = 0.45 + 0.1 * unit(rng);
      seeds.push_back({0.5 + radius * std::cos(angle), 0.5 + radius * std::sin(angle), z});
    } else {
      seeds.push_back({0.3 + 0.4 * unit(rng), 0.3 + 0.4 * unit(rng), 0.3 + 0.4 * unit(rng)});
    }
  }
  Runs r{volume, seeds, {}, 0.0f, 0.0, std::nullopt, nullptr};
  if (request.backend != "cpu") {
    const BackendChoice choice = chooseBackend(request, BackendUse::Trace);
    r.context.emplace(createContext(request, choice));
    r.tracer = std::make_unique<gpu::GpuTracer>(*r.context, choice.backend, volume);
    r.tracer->timeKernels(true);
  }
  r.duration = duration;
  r.tau = chooseStepSize(flow::StepMode::Time, std::nullopt, volume);
  const std::vector<float> multiples{64.0f, 32.0f, 16.0f, 8.0f, 4.0f, 2.0f, 1.0f, 0.5f};
  if (rotation) {
    for (const glm::dvec3& seed : seeds) r.reference.push_back(exactEnd(seed, duration));
  } else {
    const flow::TraceSet reference = traceEnds(r, "rk45", 1e-8f, nullptr);
    for (std::size_t line = 0; line < reference.lineCount(); ++line)
      r.reference.push_back(glm::dvec3(reference.positions[reference.firstPoint(line)]));
  }

  fmt::print(
      "# builtin:{}, {} cells, finest cell {:.3g}, {} interpolant; {} seeds, time mode "
      "for {:g} (tau = {:.3g}), endpoints; backend {}\n\n",
      dataset, cells.cellCount(), volume.transform.spacing.x, rotation ? "linear" : "tent",
      seedCount, duration, r.tau, request.backend);
  fmt::print(
      "| integrator | step / tolerance | steps | particle-steps/s | RMS error (cells) | "
      "max error (cells) | seconds |\n|---|---|---|---|---|---|---|\n");
  std::vector<Run> runs;
  const auto add = [&](const std::string& integrator, float setting) {
    const Run run = runOnce(r, integrator, setting);
    fmt::print("| {} | {:.3g} | {} | {:.3g} | {:.3g} | {:.3g} | {:.4f} |\n", run.integrator,
               run.setting, run.steps, double(run.steps) / run.seconds, run.rmsError, run.maxError,
               run.seconds);
    std::fflush(stdout);
    runs.push_back(run);
  };
  for (const char* integrator : {"euler", "rk2", "rk4"})
    for (float multiple : multiples) add(integrator, multiple * r.tau);
  for (float tolerance : {1e-1f, 1e-2f, 1e-3f, 1e-4f, 1e-5f, 1e-6f}) add("rk45", tolerance);

  fmt::print("\n| RMS error at most (cells) | euler | rk2 | rk4 | rk45 |\n|---|---|---|---|---|\n");
  for (double target : {1.0, 1e-1, 1e-2, 1e-3, 5e-4}) {
    std::string row = fmt::format("| {:g} |", target);
    for (const char* integrator : {"euler", "rk2", "rk4", "rk45"}) {
      std::optional<Run> best;
      for (const Run& run : runs)
        if (run.integrator == integrator && run.rmsError <= target &&
            (!best || run.seconds < best->seconds))
          best = run;
      row += best ? fmt::format(" {:.4f} s, {} steps ({:.3g}) |", best->seconds, best->steps,
                                best->setting)
                  : std::string(" not reached |");
    }
    fmt::print("{}\n", row);
  }
  return 0;
}
