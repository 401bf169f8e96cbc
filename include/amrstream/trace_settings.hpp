#pragma once
// The stepping settings as users give them (names as on the command line), checked and turned
// into the tracer's TraceOptions.

#include <cstdint>
#include <optional>
#include <string>

#include "flow/trace_options.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

struct TraceSettings {
  std::uint32_t steps = 1000;      // at most this many steps per line
  std::optional<float> stepSize;   // default: see chooseStepSize
  std::string stepMode = "arc";    // arc, cell (the paper's) or time: see docs/cli.md
  std::string integrator = "rk4";  // rk4, rk45, rk2 or euler
  float tolerance = 1e-4f;         // rk45: error per step, in finest cell widths of its region
  std::optional<float> minStep;    // rk45: default the first step / 100
  std::optional<float> maxStep;    // rk45: default the first step x 4
  std::string direction = "both";  // forward, backward or both (two lines per seed)
  float terminalSpeed = 1e-12f;
  float maxLength = 0.0f;  // 0: no limit
  float maxTime = 0.0f;    // 0: no limit
  bool vorticity = false;
  bool keepHistory = true;         // false: only each line's last point
  std::uint64_t memoryBudget = 0;  // 0: automatic
  std::uint32_t cpuTail = 0;       // TraceOptions::cpuTailLines: GPU lines the CPU finishes
};

// The settings checked (InputError naming the setting) against the volume. The collected traces
// may take at most a share of the machine's memory (kTraceMemoryShare).
flow::TraceOptions traceOptions(const TraceSettings& settings, const flow::VectorVolume& volume);

// "cell", "time" or "arc"; InputError otherwise.
flow::StepMode parseStepMode(const std::string& name);
std::string stepModeName(flow::StepMode mode);  // "cell", "time", "arc"
// "rk4", "rk45", "rk2" or "euler"; InputError otherwise.
flow::Integrator parseIntegrator(const std::string& name);
std::string integratorName(flow::Integrator integrator);
// "forward", "backward" or "both"; InputError otherwise.
flow::Direction parseDirection(const std::string& name);
std::string directionName(flow::Direction direction);  // "forward", "backward", "both"

// The step size the user gave, else the default of the mode: 0.25 cell widths, or for `time`
// 1/4 of the finest cell crossed at the volume's maximum speed. Throws InputError unless > 0.
float chooseStepSize(flow::StepMode mode, std::optional<float> requested,
                     const flow::VectorVolume& volume);

}  // namespace amrstream
