#pragma once
// The streamline integrator (DESIGN.md section 6): RK4 with the step mode's direction scaling,
// terminated with VTK's ReasonForTermination codes. The CPU reference of the GLSL integrator.

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <span>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "../../shaders/glsl/shared/trace_params.h"
#include "trace_set.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

enum class StepMode : int {
  Cell = AMRSTREAM_STEP_CELL,
  Time = AMRSTREAM_STEP_TIME,
  Arc = AMRSTREAM_STEP_ARC,
};

struct TraceOptions {
  StepMode stepMode = StepMode::Cell;
  float stepSize = 0.25f;         // h: cell widths (cell, arc) or physical time (time)
  std::uint32_t maxSteps = 1000;  // a trace holds at most maxSteps + 1 points
  float terminalSpeed = 1e-12f;   // stagnation below this speed (physical units)
  float maxLength = 0.0f;         // physical arc length limit; 0 means none
  bool keepHistory = true;        // false: store only each trace's last point
};

// The dispatch parameters shared with the GPU kernels, for `seedCount` seeds.
shared::TraceParams makeTraceParams(const VectorVolume& volume, const TraceOptions& options,
                                    std::size_t seedCount);

// Traces every seed (physical coordinates) in parallel over all cores. `progress`, when set, is
// called from worker threads with the number of seeds finished so far.
TraceSet traceStreamlines(const VectorVolume& volume, std::span<const glm::dvec3> seeds,
                          const TraceOptions& options,
                          const std::function<void(std::size_t)>& progress = {});

}  // namespace amrstream::flow
