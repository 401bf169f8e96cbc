#pragma once
// Lines handed between ranks: the states of lines that left a rank's part go to the ranks that
// own where they are, in one batch per pair of ranks per round, with non-blocking sends.

#include <vector>

#include "../../shaders/glsl/shared/line_state.h"
#include "amrstream/mpi_world.hpp"

namespace amrstream::mpi {

// Collective. outgoing[r]: the states this rank sends to rank r (its own entry is ignored).
// Returns the states the other ranks sent here, by sending rank, each batch in its order.
std::vector<shared::LineState> exchangeLines(
    const MpiWorld& world, const std::vector<std::vector<shared::LineState>>& outgoing);

}  // namespace amrstream::mpi
