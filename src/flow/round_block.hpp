#pragma once
// What one tracing round hands over: for each line it advanced (in the order the round took
// them) its LineRound, and the points it emitted, line after line in that order.

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "../../shaders/glsl/shared/line_state.h"
#include "column.hpp"

namespace amrstream::flow {

// A line's points in a round: they follow the points of the lines before it in the round.
struct LinePoints {
  std::uint32_t line;
  std::uint32_t points;
};

struct RoundBlock {
  std::vector<shared::LineRound> lines;
  Column<glm::vec3> positions;     // physical coordinates
  Column<glm::vec3> positionsLow;  // empty, or one per point: see TraceSet::precisePositions
  Column<float> times;
  Column<glm::vec3> vectors;
  Column<float> channels;       // channelCount values per point
  Column<glm::vec3> vorticity;  // empty without vorticity
};

}  // namespace amrstream::flow
