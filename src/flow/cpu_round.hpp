#pragma once
// One round of the CPU reference over a set of live lines, for tracers that manage the lines
// themselves (the round tracer of integrator.hpp, MPI ranks that hand lines to each other).

#include <functional>
#include <span>
#include <vector>

#include "../../shaders/glsl/shared/line_state.h"
#include "../../shaders/glsl/shared/trace_params.h"
#include "integrator.hpp"
#include "round_block.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

// Advances every line of `live` by at most params.roundSteps steps, on all cores: each line's
// points, then the block in line order with its point data. `live` keeps the lines that go on,
// their states moved on. `lineEnded` is called from the worker threads as lines end.
RoundBlock traceCpuRound(
    const VectorVolume& volume, const shared::TraceParams& params, const TraceOptions& options,
    std::vector<shared::LineState>& live, const std::function<void()>& lineEnded = [] {});

// Traces `lines` (states of earlier rounds, any tracer's) to their end on all cores, in batches
// and rounds within options' memory budget, handing each round's block to `consume`.
void traceCpuToEnd(
    const VectorVolume& volume, std::span<const shared::LineState> lines,
    const TraceOptions& options, const std::function<void(RoundBlock&&)>& consume,
    const std::function<void()>& lineEnded = [] {});

}  // namespace amrstream::flow
