#pragma once
// Streamline tracing options: the step mode and size, the integrator, the limits that end a line,
// the memory budget of the rounds; and the round parameters the GPU kernels read, made from them.

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <optional>

#include "../../shaders/glsl/shared/trace_codes.h"
#include "../../shaders/glsl/shared/trace_params.h"
#include "vector_volume.hpp"

namespace amrstream::flow {

enum class StepMode : int {
  Cell = AMRSTREAM_STEP_CELL,
  Time = AMRSTREAM_STEP_TIME,
  Arc = AMRSTREAM_STEP_ARC,
};

enum class Integrator : int {
  Rk4 = AMRSTREAM_INTEGRATOR_RK4,
  Rk2 = AMRSTREAM_INTEGRATOR_RK2,
  Euler = AMRSTREAM_INTEGRATOR_EULER,
  Rk45 = AMRSTREAM_INTEGRATOR_RK45,
};

// vtkStreamTracer's IntegrationDirection: Both traces each seed forward and backward, two lines.
enum class Direction { Forward, Backward, Both };

struct TraceOptions {
  StepMode stepMode = StepMode::Cell;
  float stepSize = 0.25f;  // h: cell widths (cell, arc) or physical time (time)
  Integrator integrator = Integrator::Rk4;
  // rk45 only: the error allowed per step, in finest cell widths of the step's region, and the
  // bounds of the adaptive step (in stepSize's units; stepSize is the first step tried).
  float tolerance = 1e-4f;
  float minStep = 0.0025f;
  float maxStep = 1.0f;
  std::uint32_t maxSteps = 1000;  // a line holds at most maxSteps + 1 points
  float terminalSpeed = 1e-12f;   // stagnation below this speed (physical units)
  float maxLength = 0.0f;         // physical arc length limit; 0 means none
  float maxTime = 0.0f;           // |IntegrationTime| limit, the last step shortened to meet it
  Direction direction = Direction::Both;
  bool keepHistory = true;  // false: store only each line's last point
  bool vorticity = false;   // sample the curl of the vector at every point
  // Bytes the rounds' working buffers may take (device and host staging; the collected result
  // is not counted). Sets the steps per round and the lines traced at once. 0: automatic, room
  // for rounds of 64 steps within 256 MiB .. 2 GiB (line_plan.hpp).
  std::uint64_t memoryBudget = 0;
  std::uint32_t roundSteps = 0;  // steps per round; 0: as many as the budget allows
  // GPU traces: once a round leaves this many live lines or fewer, the CPU reference finishes
  // them on all cores, where a lone line's step is faster than on a GPU (0: never; never either
  // when the volume's host values were released). Without history and roundSteps, the GPU then
  // runs rounds of an eighth of maxSteps, at least 1000, so that the lines' ends are seen.
  std::uint32_t cpuTailLines = 0;
  // Lines pause, as at a round's end, after a step that ends outside this box (finest-cell
  // units, [lower, upper)): MPI ranks tracing over data then hand them on.
  struct Box {
    glm::vec3 lower, upper;
    // Whether the point anchor + offset lies in the box, in the kernels' float arithmetic (twin
    // of outsidePauseBox() in line_round.glsl).
    bool contains(glm::ivec3 anchor, glm::vec3 offset) const {
      const glm::vec3 p = glm::vec3(anchor) + offset;
      return glm::all(glm::greaterThanEqual(p, lower)) && glm::all(glm::lessThan(p, upper));
    }
  };
  std::optional<Box> pauseOutside;
  // The collected traces may take at most this many bytes (0: no limit): tracing stops with an
  // InputError once they grow past it, rather than exhausting the machine's memory.
  std::uint64_t maxResultBytes = 0;
};

// The round parameters shared with the GPU kernels; lineCount, roundSteps and pointsPerLine are
// set per round.
shared::TraceParams makeTraceParams(const VectorVolume& volume, const TraceOptions& options);

// Called with the lines finished so far and the number of lines.
using TraceProgress = std::function<void(std::size_t finished, std::size_t lines)>;

}  // namespace amrstream::flow
