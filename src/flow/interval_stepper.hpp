#pragma once
// What PathlineTracer hands a device that steps its particles through one interval: the
// particles' positions and the steps each group of them takes, planned on the host in double
// precision; and what the device hands back, step by step (src/gpu/pathline_stepper.hpp).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <span>

#include "../../shaders/glsl/shared/pathline_stage.h"

namespace amrstream::flow {

// The particles moving through an interval, in the order the tracer lists them.
struct IntervalPlan {
  std::span<const glm::vec3> positions;   // physical: where each particle is when it starts
  std::span<const std::uint32_t> groups;  // each particle's group: its row of the schedule
  // Group-major: group g's step j at g * stepCount + j; steps past a group's last are not taken.
  std::span<const shared::PathlineStep> schedule;
  std::uint32_t stepCount = 0;
};

// Steps [firstStep, firstStep + rows) of the interval, row-major (step, then particle): each
// particle's status in the step (AMRSTREAM_REASON_RUNNING with its new point and the vector
// there, another reason where it stopped in that step, AMRSTREAM_PATHLINE_NO_STEP where it took
// none); and where a point was emitted, the snapshots' point-data channels there (channelCount per
// slot, NaN where a snapshot has no value).
struct StepRows {
  std::uint32_t firstStep = 0, rows = 0;
  std::span<const std::int32_t> status;
  std::span<const glm::vec3> positions, vectors;
  std::size_t channelCount = 0;
  std::span<const float> channelsA, channelsB;
};

class IntervalStepper {
 public:
  virtual ~IntervalStepper() = default;
  // The most particles one move() takes: the tracer hands it more in several.
  virtual std::size_t mostParticles() const = 0;
  // Takes every step of `plan` with RK4, each stage's vector interpolated in time between the
  // interval's two snapshots as the CPU tracer does, and calls `collect` with the steps in order,
  // a round of rows at a time.
  virtual void move(const IntervalPlan& plan,
                    const std::function<void(const StepRows&)>& collect) = 0;
};

}  // namespace amrstream::flow
