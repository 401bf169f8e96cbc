#include "trace_settings.hpp"

#include <algorithm>
#include <cstdlib>

#include "util/input_error.hpp"

namespace amrstream::cli {

flow::StepMode parseStepMode(const std::string& name) {
  if (name == "time") return flow::StepMode::Time;
  if (name == "arc") return flow::StepMode::Arc;
  return flow::StepMode::Cell;
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

bool validationRequested() {
  const char* setting = std::getenv("AMRSTREAM_VALIDATION");
#ifdef NDEBUG
  return setting && std::string(setting) == "1";
#else
  return !(setting && std::string(setting) == "0");
#endif
}

}  // namespace amrstream::cli
