#pragma once
// The lines a trace starts with, and how rounds share a memory budget between lines and steps.

#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "../../shaders/glsl/shared/line_state.h"
#include "column.hpp"
#include "trace_accumulator.hpp"
#include "trace_options.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

// One line per seed and direction, in vtkStreamTracer's order (all forward lines, then all
// backward ones): their starting states (seed in cell units, nothing traced) and layout.
struct LinePlan {
  Column<shared::LineState> states;  // filled in parallel, without a zero fill first
  LineLayout layout;
};
LinePlan planLines(const VectorVolume& volume, std::span<const glm::dvec3> seeds,
                   Direction direction);

// A TraceSet without lines that names what the traces of `volume` with `options` carry: the
// vector and channel names, vorticity, and the periodic box.
TraceSet traceShape(const VectorVolume& volume, const TraceOptions& options);

// What a tracer's rounds hold per line and per output slot of a round, and the bounds of its
// automatic budget.
struct RoundCosts {
  std::uint64_t bytesPerLine = 0;
  std::uint64_t bytesPerPointSlot = 0;
  std::uint64_t leastBudget = std::uint64_t(256) << 20;
  std::uint64_t mostBudget = std::uint64_t(2) << 30;
  std::uint64_t stepsPerLine = 64;  // what the automatic budget makes room for, with history
};

// The working memory of rounds: options.memoryBudget, or when it is 0 room for every line to take
// costs.stepsPerLine steps per round, within costs.leastBudget and costs.mostBudget.
std::uint64_t memoryBudget(const TraceOptions& options, const RoundCosts& costs, std::size_t lines);

// Lines traced together: as many as fit the budget with the smallest round (2 output slots per
// line with history, 1 without), at least 1.
std::size_t linesPerBatch(const TraceOptions& options, const RoundCosts& costs, std::size_t lines);

// Output slots a batch's rounds share: what the budget leaves after the lines' own bytes, at least
// one round of the smallest size.
std::uint64_t pointSlots(const TraceOptions& options, const RoundCosts& costs,
                         std::size_t batchLines);

// Steps of the next round of `liveLines` lines sharing `slots` output slots: options.roundSteps
// when set (as far as the slots allow), else as many as the slots hold with history, else all.
std::uint32_t stepsPerRound(const TraceOptions& options, std::uint64_t slots,
                            std::size_t liveLines);

// Output slots per line of a round of `steps` steps.
inline std::uint32_t pointsPerLine(const TraceOptions& options, std::uint32_t steps) {
  return options.keepHistory ? steps + 1 : 1;
}

}  // namespace amrstream::flow
