#include "trace_options.hpp"

namespace amrstream::flow {

shared::TraceParams makeTraceParams(const VectorVolume& volume, const TraceOptions& options) {
  const glm::dvec3 spacing = volume.transform.spacing;
  shared::TraceParams params{};
  params.domainLower = volume.domain.lower;
  params.domainUpper = volume.domain.upper;
  params.cellsPerPhysical = glm::vec3(1.0 / spacing);
  params.physicalCellWidth = float(glm::min(spacing.x, glm::min(spacing.y, spacing.z)));
  params.spacing = glm::vec3(spacing);
  params.stepMode = static_cast<int>(options.stepMode);
  params.period = volume.period();
  for (int a = 0; a < 3; ++a) params.periodicAxes |= volume.periodic[a] ? 1u << a : 0u;
  params.stepSize = options.stepSize;
  params.integrator = static_cast<int>(options.integrator);
  params.toleranceSquared = options.tolerance * options.tolerance;
  params.minStep = options.minStep;
  params.maxStep = options.maxStep;
  params.maxSteps = options.maxSteps;
  params.terminalSpeed = options.terminalSpeed;
  params.maxLength = options.maxLength;
  params.maxTime = options.maxTime;
  params.keepHistory = options.keepHistory ? 1u : 0u;
  params.linearInterpolant = volume.interpolant == Interpolant::Linear ? 1u : 0u;
  params.deepPositions = volume.deepPositions() ? 1u : 0u;
  if (options.pauseOutside) {
    params.pauseOutside = 1u;
    params.pauseLower = options.pauseOutside->lower;
    params.pauseUpper = options.pauseOutside->upper;
  }
  return params;
}

}  // namespace amrstream::flow
