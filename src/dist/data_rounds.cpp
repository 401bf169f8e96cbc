#include "data_rounds.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "flow/cpu_round.hpp"
#include "flow/line_plan.hpp"
#include "line_exchange.hpp"
#include "util/input_error.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::dist {

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

}  // namespace

double stageReach(const flow::VectorVolume& volume, const flow::TraceOptions& options) {
  if (options.integrator == flow::Integrator::Rk45)
    throw InputError("--distribute data", "is not available with --integrator rk45 (its stages "
                                          "reach several steps out); use rk4, rk2 or euler");
  if (volume.interpolant == flow::Interpolant::Linear)
    throw InputError("--distribute data", "is not available with --interpolant linear");
  float widest = 0.0f;
  for (const shared::Region& region : volume.regions.regions)
    widest = std::max(widest, region.finestCellWidth);
  float fastest = 0.0f;
  for (const glm::vec3& v : volume.values) fastest = std::max(fastest, glm::length(v));
  const double h = options.stepSize;
  switch (options.stepMode) {
    case flow::StepMode::Arc:
      return h * widest;
    case flow::StepMode::Cell:
      return h * widest * fastest;
    case flow::StepMode::Time: {
      const glm::dvec3 perPhysical = 1.0 / volume.transform.spacing;
      return h * fastest * std::max({perPhysical.x, perPhysical.y, perPhysical.z});
    }
  }
  return 0.0;
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

RoundAdvance cpuRoundAdvance(const flow::VectorVolume& volume,
                             const flow::TraceOptions& options) {
  shared::TraceParams params = flow::makeTraceParams(volume, options);
  return [&volume, options, params](std::vector<shared::LineState>& live) mutable {
    params.lineCount = std::uint32_t(live.size());
    params.roundSteps =
        flow::stepsPerRound(options, flow::cpuPointSlots(options, live.size()), live.size());
    params.pointsPerLine = flow::pointsPerLine(options, params.roundSteps);
    return flow::traceCpuRound(volume, params, options, live);
  };
}

flow::TraceSet traceOverData(const MpiWorld& world, const flow::VectorVolume& volume,
                             const DataPartition& partition,
                             std::vector<shared::LineState> owned,
                             const flow::TraceOptions& options, const RoundAdvance& advance,
                             DataRoundStats* stats) {
  DataRoundStats local;
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

}  // namespace amrstream::dist
