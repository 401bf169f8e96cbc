#include "double_tracer.hpp"

#include <optional>

namespace amrstream::testing {

DoubleTracer::DoubleTracer(const bricks::AmrField& field, const std::array<std::string, 3>& vector)
    : field_(field, vector), transform_(field.transform()) {}

DoubleTrace DoubleTracer::trace(glm::dvec3 seed, double h, std::uint32_t steps) const {
  const glm::dvec3 cellsPerPhysical = 1.0 / transform_.spacing;
  DoubleTrace trace{{seed}, DoubleTraceEnd::StepsDone};
  // The stage vector at p, or none when p ends the trace (which trace.end then says).
  const auto stage = [&](glm::dvec3 p) -> std::optional<glm::dvec3> {
    const TentSample s = field_.sample(p);
    if (s.status == TentSample::Status::Valid) return h * s.value * cellsPerPhysical;
    trace.end = s.status == TentSample::Status::OutOfDomain ? DoubleTraceEnd::OutOfDomain
                                                            : DoubleTraceEnd::InvalidSample;
    return std::nullopt;
  };

  glm::dvec3 x = transform_.toCellUnits(seed);
  std::optional<glm::dvec3> k1 = stage(x);
  for (std::uint32_t n = 0; n < steps && k1; ++n) {
    const std::optional<glm::dvec3> k2 = stage(x + 0.5 * *k1);
    if (!k2) break;
    const std::optional<glm::dvec3> k3 = stage(x + 0.5 * *k2);
    if (!k3) break;
    const std::optional<glm::dvec3> k4 = stage(x + *k3);
    if (!k4) break;
    const glm::dvec3 next = x + (*k1 + 2.0 * *k2 + 2.0 * *k3 + *k4) / 6.0;
    k1 = stage(next);  // the next step's first stage, or the end of the trace
    if (!k1) break;
    x = next;
    trace.positions.push_back(transform_.toPhysical(x));
  }
  return trace;
}

}  // namespace amrstream::testing
