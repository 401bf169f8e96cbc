#include "line_plan.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "cell_point.hpp"

namespace amrstream::flow {

LinePlan planLines(const VectorVolume& volume, std::span<const glm::dvec3> seeds,
                   Direction direction) {
  std::vector<float> signs;
  if (direction != Direction::Backward) signs.push_back(1.0f);
  if (direction != Direction::Forward) signs.push_back(-1.0f);
  LinePlan plan;
  const std::size_t lines = signs.size() * seeds.size();
  plan.states.resize(lines);
  plan.layout.seedIds.resize(lines);
  plan.layout.directions.resize(lines);
  tbb::parallel_for(std::size_t(0), lines, [&](std::size_t line) {
    const std::size_t seed = line % seeds.size();
    const float sign = signs[line / seeds.size()];
    // Without deep positions the anchor stays zero (line_tracer.cpp).
    const glm::dvec3 cells = volume.transform.toCellUnits(seeds[seed]);
    const CellPoint start =
        volume.deepPositions() ? toCellPoint(cells) : CellPoint(glm::vec3(cells));
    plan.states[line] = {start.offset, 0.0f, 0.0f,        0u, static_cast<std::uint32_t>(line),
                         sign,         0.0f, start.anchor};
    plan.layout.seedIds[line] = static_cast<std::uint32_t>(seed);
    plan.layout.directions[line] = sign;
  });
  return plan;
}

TraceSet traceShape(const VectorVolume& volume, const TraceOptions& options) {
  TraceSet shape;
  shape.vectorName = volume.vectorName;
  shape.channelNames = volume.channelNames;
  shape.withVorticity = options.vorticity;
  shape.precisePositions = volume.deepPositions();
  shape.periodic = {volume.periodic, volume.transform.toPhysical(glm::dvec3(volume.domain.lower)),
                    volume.transform.toPhysical(glm::dvec3(volume.domain.upper))};
  return shape;
}

std::uint64_t memoryBudget(const TraceOptions& options, const RoundCosts& costs,
                           std::size_t lines) {
  if (options.memoryBudget > 0) return options.memoryBudget;
  const std::uint64_t slotsPerLine = options.keepHistory ? costs.stepsPerLine + 1 : 1;
  const std::uint64_t wanted =
      lines * (costs.bytesPerLine + slotsPerLine * costs.bytesPerPointSlot);
  return std::clamp(wanted, costs.leastBudget, std::max(costs.leastBudget, costs.mostBudget));
}

std::size_t linesPerBatch(const TraceOptions& options, const RoundCosts& costs, std::size_t lines) {
  const std::uint64_t perLine =
      costs.bytesPerLine + costs.bytesPerPointSlot * (options.keepHistory ? 2 : 1);
  const std::uint64_t fit =
      memoryBudget(options, costs, lines) / std::max<std::uint64_t>(1, perLine);
  return std::max<std::size_t>(1, std::min<std::uint64_t>(lines, fit));
}

std::uint64_t pointSlots(const TraceOptions& options, const RoundCosts& costs,
                         std::size_t batchLines) {
  const std::uint64_t budget = memoryBudget(options, costs, batchLines);
  const std::uint64_t lineBytes = costs.bytesPerLine * batchLines;
  const std::uint64_t left = budget > lineBytes ? budget - lineBytes : 0;
  const std::uint64_t smallest = std::uint64_t(batchLines) * (options.keepHistory ? 2 : 1);
  const std::uint64_t largest =
      std::uint64_t(batchLines) * (options.keepHistory ? std::uint64_t(options.maxSteps) + 1 : 1);
  const std::uint64_t fit = left / std::max<std::uint64_t>(1, costs.bytesPerPointSlot);
  return std::max(smallest, std::min(fit, largest));
}

std::uint32_t stepsPerRound(const TraceOptions& options, std::uint64_t slots,
                            std::size_t liveLines) {
  if (!options.keepHistory || liveLines == 0)
    return options.roundSteps > 0 ? std::min(options.roundSteps, options.maxSteps)
                                  : options.maxSteps;
  const std::uint64_t fit = std::max<std::uint64_t>(slots / liveLines, 2) - 1;
  const std::uint64_t wanted = options.roundSteps > 0 ? options.roundSteps : options.maxSteps;
  return static_cast<std::uint32_t>(std::max<std::uint64_t>(1, std::min(fit, wanted)));
}

}  // namespace amrstream::flow
