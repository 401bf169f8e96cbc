#include "data_rounds.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "../../shaders/glsl/shared/dormand_prince.h"
#include "amrstream/error.hpp"
#include "flow/cpu_tracer.hpp"
#include "flow/line_plan.hpp"
#include "line_exchange.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::mpi {

namespace {

template <typename Column>
void append(Column& to, const Column& from) {
  to.insert(to.end(), from.begin(), from.end());
}

// The round's lines as runs.
void appendRuns(flow::TraceSet& runs, const flow::RoundBlock& block) {
  for (const shared::LineRound& line : block.lines) {
    runs.seedIds.push_back(line.line);
    runs.directions.push_back(0.0f);
    runs.steps.push_back(line.steps);
    runs.reasons.push_back(line.reason);
    runs.offsets.push_back(runs.offsets.back() + line.points);
  }
  append(runs.positions, block.positions);
  append(runs.positionsLow, block.positionsLow);
  append(runs.times, block.times);
  append(runs.vectors, block.vectors);
  append(runs.channels, block.channels);
  append(runs.vorticity, block.vorticity);
}

constexpr double mag(float w) { return w < 0.0f ? -double(w) : double(w); }

// The largest sum of the weights' magnitudes over Dormand and Prince's stages, and over the
// step's (fifth-order) weights.
constexpr double kDpStageWeights = std::max(
    {mag(AMRSTREAM_DP_A21), mag(AMRSTREAM_DP_A31) + mag(AMRSTREAM_DP_A32),
     mag(AMRSTREAM_DP_A41) + mag(AMRSTREAM_DP_A42) + mag(AMRSTREAM_DP_A43),
     mag(AMRSTREAM_DP_A51) + mag(AMRSTREAM_DP_A52) + mag(AMRSTREAM_DP_A53) + mag(AMRSTREAM_DP_A54),
     mag(AMRSTREAM_DP_A61) + mag(AMRSTREAM_DP_A62) + mag(AMRSTREAM_DP_A63) + mag(AMRSTREAM_DP_A64) +
         mag(AMRSTREAM_DP_A65)});
constexpr double kDpStepWeights = mag(AMRSTREAM_DP_B1) + mag(AMRSTREAM_DP_B3) +
                                  mag(AMRSTREAM_DP_B4) + mag(AMRSTREAM_DP_B5) +
                                  mag(AMRSTREAM_DP_B6);
static_assert(kDpStageWeights > 24.6 && kDpStageWeights < 24.7);

}  // namespace

StepReach stepReach(const flow::VectorVolume& volume, const flow::TraceOptions& options,
                    std::optional<double> knownFastest) {
  float widest = 0.0f;
  for (const shared::Region& region : volume.regions.regions)
    widest = std::max(widest, region.finestCellWidth);
  double fastest = 0.0;  // arc mode's reach does not depend on it
  if (knownFastest) {
    fastest = *knownFastest;
  } else if (options.stepMode != flow::StepMode::Arc) {
    for (const glm::vec3& v : volume.values) fastest = std::max(fastest, double(glm::length(v)));
    if (volume.interpolant == flow::Interpolant::Linear) {
      // Three gradients (one per component) per value slot, in values per finest cell.
      double steepest = 0.0;
      const std::vector<glm::vec3>& g = volume.vectorGradients;
      for (std::size_t slot = 0; slot + 2 < g.size(); slot += 3)
        steepest = std::max(steepest, std::sqrt(double(glm::dot(g[slot], g[slot]) +
                                                       glm::dot(g[slot + 1], g[slot + 1]) +
                                                       glm::dot(g[slot + 2], g[slot + 2]))));
      fastest += steepest * 0.5 * std::sqrt(3.0) * widest;
    }
  }
  const bool rk45 = options.integrator == flow::Integrator::Rk45;
  const double h = rk45 ? std::max(options.maxStep, options.stepSize) : options.stepSize;
  double stage = 0.0;
  switch (options.stepMode) {
    case flow::StepMode::Arc:
      stage = h * widest;
      break;
    case flow::StepMode::Cell:
      stage = h * widest * fastest;
      break;
    case flow::StepMode::Time: {
      const glm::dvec3 perPhysical = 1.0 / volume.transform.spacing;
      stage = h * fastest * std::max({perPhysical.x, perPhysical.y, perPhysical.z});
      break;
    }
  }
  if (rk45) return {kDpStepWeights * stage, kDpStageWeights * stage};
  return {stage, stage};
}

flow::TraceOptions::Box pauseBox(const DataPartition& partition, int rank, double margin,
                                 const flow::PeriodicAxes& periodic) {
  glm::ivec3 domainLower = partition.lower.front(), domainUpper = partition.upper.front();
  for (int k = 0; k < partition.parts(); ++k) {
    domainLower = glm::min(domainLower, partition.lower[std::size_t(k)]);
    domainUpper = glm::max(domainUpper, partition.upper[std::size_t(k)]);
  }
  constexpr float kBeyond = 0x1p30f;
  const glm::ivec3 lower = partition.lower[std::size_t(rank)];
  const glm::ivec3 upper = partition.upper[std::size_t(rank)];
  flow::TraceOptions::Box box;
  for (int a = 0; a < 3; ++a) {
    box.lower[a] = lower[a] == domainLower[a] && !periodic[a] ? -kBeyond : float(lower[a] - margin);
    box.upper[a] = upper[a] == domainUpper[a] && !periodic[a] ? kBeyond : float(upper[a] + margin);
  }
  return box;
}

RoundAdvance cpuRoundAdvance(const flow::VectorVolume& volume, const flow::TraceOptions& options) {
  shared::TraceParams params = flow::makeTraceParams(volume, options);
  return [&volume, options, params](std::vector<shared::LineState>& live) mutable {
    params.lineCount = std::uint32_t(live.size());
    params.roundSteps =
        flow::stepsPerRound(options, flow::cpuPointSlots(options, live.size()), live.size());
    params.pointsPerLine = flow::pointsPerLine(options, params.roundSteps);
    return flow::traceCpuRound(volume, params, options, live);
  };
}

flow::TraceSet traceInRounds(const MpiWorld& world, const flow::VectorVolume& volume,
                             std::vector<shared::LineState> owned,
                             const flow::TraceOptions& options, const RoundAdvance& advance,
                             const LineRouting& route, RoundStats* stats) {
  RoundStats local;
  flow::TraceSet runs = flow::traceShape(volume, options);
  std::vector<shared::LineState>& live = owned;
  Stopwatch clock;
  for (;;) {
    clock.restart();
    if (!live.empty()) appendRuns(runs, advance(live));
    local.traceSeconds += clock.seconds();
    ++local.rounds;

    clock.restart();
    std::vector<std::vector<shared::LineState>> outgoing(std::size_t(world.size()));
    route(live, outgoing);
    for (const auto& batch : outgoing) local.linesSent += batch.size();
    const std::vector<shared::LineState> arrived = exchangeLines(world, outgoing);
    live.insert(live.end(), arrived.begin(), arrived.end());
    const double running = world.sumOverRanks(double(live.size()));
    local.exchangeSeconds += clock.seconds();
    if (running == 0.0) break;
  }
  if (stats) *stats = local;
  return runs;
}

flow::TraceSet traceOverData(const MpiWorld& world, const flow::VectorVolume& volume,
                             const DataPartition& partition, std::vector<shared::LineState> owned,
                             const flow::TraceOptions& options, const RoundAdvance& advance,
                             RoundStats* stats) {
  const LineRouting toOwners = [&](std::vector<shared::LineState>& live,
                                   std::vector<std::vector<shared::LineState>>& outgoing) {
    std::size_t kept = 0;
    for (const shared::LineState& s : live) {
      const bool stays = options.pauseOutside && options.pauseOutside->contains(s.anchor, s.offset);
      const int owner = stays ? world.rank() : partition.ownerOf(cellPointOf(s));
      if (owner == world.rank())
        live[kept++] = s;
      else
        outgoing[std::size_t(owner)].push_back(s);
    }
    live.resize(kept);
  };
  return traceInRounds(world, volume, std::move(owned), options, advance, toOwners, stats);
}

}  // namespace amrstream::mpi
