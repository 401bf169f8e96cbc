#pragma once
// The CPU reference tracer: RK4 (or the chosen integrator) with the step mode's direction scaling
// (docs/architecture.md, "Integration") on all cores, in rounds of steps whose points are collected
// into a TraceSet (trace_accumulator.hpp), terminated with VTK's ReasonForTermination codes. Also
// one round over a set of live lines, for tracers that manage the lines themselves (the round
// tracer of round_tracer.hpp, MPI ranks that hand lines to each other).

#include <functional>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "../../shaders/glsl/shared/line_state.h"
#include "../../shaders/glsl/shared/trace_params.h"
#include "round_block.hpp"
#include "stored_traces.hpp"
#include "trace_options.hpp"
#include "trace_set.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

// Output slots the CPU reference's rounds of `lines` lines share within options' budget.
std::uint64_t cpuPointSlots(const TraceOptions& options, std::size_t lines);

// Traces every seed (physical coordinates) in the options' directions on all cores. `progress`,
// when set, is called with the lines finished so far and the number of lines.
TraceSet traceStreamlines(const VectorVolume& volume, std::span<const glm::dvec3> seeds,
                          const TraceOptions& options, const TraceProgress& progress = {});
// The same, the points left in the rounds that made them (read line by line; assemble() gives the
// TraceSet): what writers of large results want.
StoredTraces traceToRounds(const VectorVolume& volume, std::span<const glm::dvec3> seeds,
                           const TraceOptions& options, const TraceProgress& progress = {});

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
