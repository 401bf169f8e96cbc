#pragma once
// The stepping settings as users give them (names as on the command line); the library checks
// them against the field when a job is prepared.

#include <cstdint>
#include <optional>
#include <string>

#include "amrstream/settings.hpp"

namespace amrstream {

// Each member is the setting of amrstream/settings.hpp its comment names, with its default.
struct TraceSettings {
  std::uint32_t steps = std::uint32_t(settings::kSteps.fallback);  // steps
  std::optional<float> stepSize;  // step_size: unset, the step mode's default (chooseStepSize)
  std::string stepMode{settings::kStepMode.shown};                 // step_mode
  std::string integrator{settings::kIntegrator.shown};             // integrator
  float tolerance = float(settings::kTolerance.fallback);          // tolerance
  std::optional<float> minStep;                                    // min_step
  std::optional<float> maxStep;                                    // max_step
  std::string direction{settings::kDirection.shown};               // direction
  float terminalSpeed = float(settings::kTerminalSpeed.fallback);  // terminal_speed
  float maxLength = float(settings::kMaxLength.fallback);          // max_length
  float maxTime = float(settings::kMaxTime.fallback);              // max_time
  bool vorticity = false;                                          // vorticity
  bool keepHistory = true;  // false: only each line's last point (endpoints_only)
  std::uint64_t memoryBudget = std::uint64_t(settings::kMemoryBudget.fallback);  // memory_budget
  std::uint32_t cpuTail = std::uint32_t(settings::kCpuTail.fallback);            // cpu_tail
};

// The most memoryBudget may be: the machine's memory (any count where it is unknown).
std::uint64_t maxMemoryBudget();

}  // namespace amrstream
