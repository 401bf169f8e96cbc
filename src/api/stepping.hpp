#pragma once
// The stepping settings (amrstream/trace_settings.hpp) checked against a volume and turned into
// the tracer's options, and the names of the step modes, integrators and directions.

#include <optional>
#include <string>

#include "amrstream/trace_settings.hpp"
#include "flow/trace_options.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

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
