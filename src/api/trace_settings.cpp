#include "amrstream/trace_settings.hpp"

#include <algorithm>

#include "util/host_memory.hpp"
#include "util/input_error.hpp"

namespace amrstream {

flow::StepMode parseStepMode(const std::string& name) {
  if (name == "cell") return flow::StepMode::Cell;
  if (name == "time") return flow::StepMode::Time;
  if (name == "arc") return flow::StepMode::Arc;
  throw InputError("step mode", "'" + name + "' is not cell, time or arc");
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

flow::Direction parseDirection(const std::string& name) {
  if (name == "forward") return flow::Direction::Forward;
  if (name == "backward") return flow::Direction::Backward;
  if (name == "both") return flow::Direction::Both;
  throw InputError("direction", "'" + name + "' is not forward, backward or both");
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
  float step = flow::TraceOptions{}.stepSize;
  if (requested) {
    step = *requested;
  } else if (mode == flow::StepMode::Time) {
    float maxSpeed = 0.0f;
    for (const glm::vec3& v : volume.values) maxSpeed = std::max(maxSpeed, glm::length(v));
    const glm::dvec3 s = volume.transform.spacing;
    const double finest = std::min(s.x, std::min(s.y, s.z));
    step = maxSpeed > 0.0f ? float(0.25 * finest / maxSpeed) : 1.0f;
  }
  if (!(step > 0.0f)) throw InputError("--step-size", "the step size must be positive");
  return step;
}

flow::TraceOptions traceOptions(const TraceSettings& s, const flow::VectorVolume& volume) {
  flow::TraceOptions options;
  options.stepMode = parseStepMode(s.stepMode);
  options.stepSize = chooseStepSize(options.stepMode, s.stepSize, volume);
  options.maxSteps = s.steps;
  options.keepHistory = s.keepHistory;
  if (!(s.terminalSpeed >= 0.0f)) throw InputError("--terminal-speed", "must be 0 or positive");
  if (!(s.maxLength >= 0.0f)) throw InputError("--max-length", "must be 0 (no limit) or positive");
  if (!(s.maxTime >= 0.0f)) throw InputError("--max-time", "must be 0 (no limit) or positive");
  options.terminalSpeed = s.terminalSpeed;
  options.maxLength = s.maxLength;
  options.maxTime = s.maxTime;
  options.direction = parseDirection(s.direction);
  options.vorticity = s.vorticity;
  options.memoryBudget = s.memoryBudget;
  options.maxResultBytes = static_cast<std::uint64_t>(kTraceMemoryShare * physicalMemoryBytes());
  return options;
}

}  // namespace amrstream
