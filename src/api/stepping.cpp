#include "api/stepping.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "amrstream/error.hpp"
#include "api/trace_memory.hpp"
#include "util/host_memory.hpp"

namespace amrstream {

flow::StepMode parseStepMode(const std::string& name) {
  if (name == "cell") return flow::StepMode::Cell;
  if (name == "time") return flow::StepMode::Time;
  if (name == "arc") return flow::StepMode::Arc;
  throw settingError("step_mode", "'" + name + "' is not cell, time or arc");
}

std::string stepModeName(flow::StepMode mode) {
  switch (mode) {
    case flow::StepMode::Time:
      return "time";
    case flow::StepMode::Arc:
      return "arc";
    case flow::StepMode::Cell:
      break;
  }
  return "cell";
}

flow::Integrator parseIntegrator(const std::string& name) {
  if (name == "rk4") return flow::Integrator::Rk4;
  if (name == "rk45") return flow::Integrator::Rk45;
  if (name == "rk2") return flow::Integrator::Rk2;
  if (name == "euler") return flow::Integrator::Euler;
  throw settingError("integrator", "'" + name + "' is not rk4, rk45, rk2 or euler");
}

std::string integratorName(flow::Integrator integrator) {
  switch (integrator) {
    case flow::Integrator::Rk45:
      return "rk45";
    case flow::Integrator::Rk2:
      return "rk2";
    case flow::Integrator::Euler:
      return "euler";
    case flow::Integrator::Rk4:
      break;
  }
  return "rk4";
}

flow::Direction parseDirection(const std::string& name) {
  if (name == "forward") return flow::Direction::Forward;
  if (name == "backward") return flow::Direction::Backward;
  if (name == "both") return flow::Direction::Both;
  throw settingError("direction", "'" + name + "' is not forward, backward or both");
}

std::string directionName(flow::Direction direction) {
  switch (direction) {
    case flow::Direction::Forward:
      return "forward";
    case flow::Direction::Backward:
      return "backward";
    case flow::Direction::Both:
      break;
  }
  return "both";
}

float chooseStepSize(flow::StepMode mode, std::optional<float> requested,
                     const flow::VectorVolume& volume) {
  if (requested) {
    if (!(*requested > 0.0f) || !std::isfinite(*requested))
      throw settingError("step_size", fmt::format("{} is not a positive finite step", *requested));
    return *requested;
  }
  if (mode != flow::StepMode::Time) return flow::TraceOptions{}.stepSize;
  // A quarter of the finest cell crossed at the maximum speed (in double: |v|² of a float
  // component near 1e18 overflows float).
  double maxSpeed = 0.0;
  for (const glm::vec3& v : volume.values)
    maxSpeed = std::max(maxSpeed, glm::length(glm::dvec3(v)));
  const glm::dvec3 s = volume.transform.spacing;
  const double finest = std::min(s.x, std::min(s.y, s.z));
  const double step = maxSpeed > 0.0 ? 0.25 * finest / maxSpeed : 1.0;
  if (!(step >= double(std::numeric_limits<float>::min()) &&
        step <= double(std::numeric_limits<float>::max())))
    throw InputError(volume.vectorName,
                     fmt::format("the default time step (a quarter of the finest cell, {:g}, "
                                 "crossed at the maximum speed, {:g}) is {:g}, outside float32's "
                                 "range: give {{step_size}} or rescale the field",
                                 finest, maxSpeed, step));
  return float(step);
}

// The curl is a difference of values over a cell width: it must stay finite in float32.
void checkVorticityRange(const flow::VectorVolume& volume) {
  float maxComponent = 0.0f;
  for (const glm::vec3& v : volume.values)
    maxComponent = std::max({maxComponent, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  const glm::dvec3 s = volume.transform.spacing;
  const double finest = std::min(s.x, std::min(s.y, s.z));
  const double bound = 4.0 * double(maxComponent) / finest;
  if (!(bound <= 1e36))
    throw settingError("vorticity",
                       fmt::format("'{}' reaches {:g} over a finest cell of {:g}: its curl would "
                                   "overflow float32; rescale the field or its coordinates",
                                   volume.vectorName, maxComponent, finest));
}

std::uint64_t maxMemoryBudget() {
  const double memory = physicalMemoryBytes();
  return memory > 0.0 ? static_cast<std::uint64_t>(memory)
                      : std::numeric_limits<std::uint64_t>::max();
}

flow::TraceOptions traceOptions(const TraceSettings& s, const flow::VectorVolume& volume) {
  flow::TraceOptions options;
  options.stepMode = parseStepMode(s.stepMode);
  options.stepSize = chooseStepSize(options.stepMode, s.stepSize, volume);
  options.maxSteps = s.steps;
  options.integrator = parseIntegrator(s.integrator);
  // rk45's tolerance squared must stay a normal float (the controller reads its exponent).
  if (!(s.tolerance >= 1e-8f && s.tolerance <= 1.0f))
    throw settingError(
        "tolerance",
        fmt::format("{} is not in [1e-8, 1] (finest cell widths per step)", s.tolerance));
  options.tolerance = s.tolerance;
  options.minStep = s.minStep.value_or(options.stepSize / 100.0f);
  options.maxStep = s.maxStep.value_or(options.stepSize * 4.0f);
  if (!(options.minStep > 0.0f && std::isfinite(options.maxStep) &&
        options.minStep <= options.stepSize && options.stepSize <= options.maxStep))
    throw settingError("min_step",
                       fmt::format("rk45 needs 0 < {{min_step}} ({:g}) <= the first step ({:g}) <= "
                                   "{{max_step}} ({:g})",
                                   options.minStep, options.stepSize, options.maxStep));
  options.keepHistory = s.keepHistory;
  if (!(s.terminalSpeed >= 0.0f)) throw settingError("terminal_speed", "must be 0 or positive");
  if (!(s.maxLength >= 0.0f)) throw settingError("max_length", "must be 0 (no limit) or positive");
  if (!(s.maxTime >= 0.0f)) throw settingError("max_time", "must be 0 (no limit) or positive");
  options.terminalSpeed = s.terminalSpeed;
  options.maxLength = s.maxLength;
  options.maxTime = s.maxTime;
  options.direction = parseDirection(s.direction);
  options.vorticity = s.vorticity;
  if (s.vorticity) checkVorticityRange(volume);
  options.memoryBudget = s.memoryBudget;
  options.cpuTailLines = s.cpuTail;
  options.maxResultBytes = hostTraceLimit();
  return options;
}

}  // namespace amrstream
