#pragma once
// One line advanced by one round of at most params.roundSteps RK4 steps: the CPU twin of
// advanceLine() in shaders/glsl/include/line_round.glsl, which the GPU tests compare with it.

#include <cstdint>
#include <functional>
#include <glm/glm.hpp>

#include "../../shaders/glsl/shared/line_state.h"
#include "../../shaders/glsl/shared/trace_params.h"
#include "sampler.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

// Receives each point the line emits: its position, IntegrationTime and the sample there. With
// history: the seed (in the line's first round) and the end of every step; without: the last point,
// once the line ends.
using PointEmitter =
    std::function<void(const CellPoint& position, float time, const VectorSample& sample)>;

// Advances `state` in place and returns what the round did; the line goes on in a later round
// while the reason is AMRSTREAM_REASON_RUNNING.
shared::LineRound advanceLine(const VectorVolume& volume, const shared::TraceParams& params,
                              shared::LineState& state, const PointEmitter& emit);

}  // namespace amrstream::flow
