#pragma once
// Tracing over data (--distribute data): every rank holds the bricks of its part of space and of
// a halo around it, and advances the lines that are in its part by rounds of a few steps; after
// each round, lines that left its part go to the ranks that own where they are. The halo is wide
// enough for every stage of a round's steps to sample where the rank holds every brick whose
// tents reach, so each step is the step one process takes, bit for bit. The rounds end when no
// rank has a live line (one sum over the ranks per round, not per step).

#include <cstdint>
#include <functional>
#include <vector>

#include "../../shaders/glsl/shared/line_state.h"
#include "data_partition.hpp"
#include "flow/integrator.hpp"
#include "flow/round_block.hpp"
#include "flow/trace_set.hpp"
#include "flow/vector_volume.hpp"
#include "mpi_world.hpp"

namespace amrstream::dist {

// The farthest, in finest cells, that one stage of one step may sample from the step's start:
// from the step mode and size, the fastest cell of `volume` and its widest region cells. Throws
// InputError for what the bound does not cover (rk45, whose stages reach several steps out, and
// the linear interpolant, which may exceed the fastest cell).
double stageReach(const flow::VectorVolume& volume, const flow::TraceOptions& options);

struct DataRoundStats {
  std::uint32_t rounds = 0;
  std::uint64_t linesSent = 0;  // hand-offs from this rank
  double traceSeconds = 0.0, exchangeSeconds = 0.0;
};

// One round of a few steps over `live` on some backend: the round's block, `live` left holding
// the lines that go on.
using RoundAdvance = std::function<flow::RoundBlock(std::vector<shared::LineState>& live)>;

// A RoundAdvance on the CPU reference, rounds of `steps` steps. `volume` must outlive it.
RoundAdvance cpuRoundAdvance(const flow::VectorVolume& volume, const flow::TraceOptions& options,
                             std::uint32_t steps);

// Collective. Advances `owned` (lines whose points lie in this rank's part) to their ends, round
// after round. Returns the runs this rank traced: a TraceSet (shaped by `volume` and `options`)
// whose entries are runs (a line's points of one round on this rank), seedIds holding the line,
// steps the line's steps at the run's end and reasons its reason then (running when it went on).
flow::TraceSet traceOverData(const MpiWorld& world, const flow::VectorVolume& volume,
                             const DataPartition& partition,
                             std::vector<shared::LineState> owned,
                             const flow::TraceOptions& options, const RoundAdvance& advance,
                             DataRoundStats* stats = nullptr);

// The position of a line in finest-cell units.
inline glm::dvec3 cellPointOf(const shared::LineState& s) {
  return glm::dvec3(s.anchor) + glm::dvec3(s.offset);
}

}  // namespace amrstream::dist
