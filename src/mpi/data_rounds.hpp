#pragma once
// Tracing over data (--distribute data): every rank holds the bricks of its part of space and of
// a halo around it, and advances the lines that are in its part until they leave it by more than a
// margin, end, or fill the round's output; lines that left then go to the ranks that own where they
// are. The halo is the margin plus the farthest one step can sample, so each step is the step one
// process takes, bit for bit. The rounds end when no rank has a live line (one sum over the ranks
// per round, not per step).

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "../../shaders/glsl/shared/line_state.h"
#include "amrstream/mpi_world.hpp"
#include "data_partition.hpp"
#include "flow/round_block.hpp"
#include "flow/trace_options.hpp"
#include "flow/trace_set.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream::mpi {

// How far, in finest cells, one step may move a line from where it starts, and how far one of
// its stages may sample: from the step mode and the (largest) step size, the fastest vector the
// interpolant can give (for the linear one, the fastest cell plus its steepest gradient over half
// a diagonal of the widest cell) and the widest region cells. Rk45's stages combine earlier
// stages with weights whose magnitudes add up to 24.7, its step's to 1.65; the other integrators'
// stages and steps lie within one step.
struct StepReach {
  double step = 0.0;
  double stage = 0.0;
};
// `fastest`: the fastest vector the interpolant can give, when known from elsewhere (ranks that
// hold part of the values).
StepReach stepReach(const flow::VectorVolume& volume, const flow::TraceOptions& options,
                    std::optional<double> fastest = std::nullopt);

// The box a rank's lines stay in: its part grown by `margin` finest cells, and without bound
// beyond the faces that lie on the domain's, but for periodic axes (the points beyond have no
// other owner; along periodic axes lines wrap to the other side). A line pauses after a step
// that ends outside it (TraceOptions::pauseOutside).
flow::TraceOptions::Box pauseBox(const DataPartition& partition, int rank, double margin,
                                 const flow::PeriodicAxes& periodic);

struct RoundStats {
  std::uint32_t rounds = 0;
  std::uint64_t linesSent = 0;  // lines this rank handed to others
  double traceSeconds = 0.0, exchangeSeconds = 0.0;
};

// One round over `live` on some backend, as many steps as its output allows: the round's block,
// `live` left holding the lines that go on.
using RoundAdvance = std::function<flow::RoundBlock(std::vector<shared::LineState>& live)>;

// A RoundAdvance on the CPU reference. `volume` must outlive it.
RoundAdvance cpuRoundAdvance(const flow::VectorVolume& volume, const flow::TraceOptions& options);

// Collective (every rank calls it once a round). After a round, moves the lines of `live` that
// go to other ranks into outgoing[rank]; the rest stay in `live`, in their order.
using LineRouting = std::function<void(std::vector<shared::LineState>& live,
                                       std::vector<std::vector<shared::LineState>>& outgoing)>;

// Collective. Advances `owned` to their ends, round after round; after each round `route` sends
// lines that still run to other ranks, which go on with them. Returns the runs this rank traced: a
// TraceSet (shaped by `volume` and `options`) whose entries are runs (a line's points of one
// round on this rank), seedIds holding the line, steps the line's steps at the run's end and
// reasons its reason then (running when it went on).
flow::TraceSet traceInRounds(const MpiWorld& world, const flow::VectorVolume& volume,
                             std::vector<shared::LineState> owned,
                             const flow::TraceOptions& options, const RoundAdvance& advance,
                             const LineRouting& route, RoundStats* stats = nullptr);

// traceInRounds over data: `owned` are the lines whose points lie in this rank's part, and a line
// paused outside options.pauseOutside goes to the rank that owns its point.
flow::TraceSet traceOverData(const MpiWorld& world, const flow::VectorVolume& volume,
                             const DataPartition& partition, std::vector<shared::LineState> owned,
                             const flow::TraceOptions& options, const RoundAdvance& advance,
                             RoundStats* stats = nullptr);

// The position of a line in finest-cell units.
inline glm::dvec3 cellPointOf(const shared::LineState& s) {
  return glm::dvec3(s.anchor) + glm::dvec3(s.offset);
}

}  // namespace amrstream::mpi
