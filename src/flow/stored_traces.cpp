#include "stored_traces.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <stdexcept>

namespace amrstream::flow {

namespace {

const float* columnData(const RoundBlock& block, PointColumn column) {
  switch (column) {
    case PointColumn::Positions:
      return reinterpret_cast<const float*>(block.positions.data());
    case PointColumn::PositionsLow:
      return reinterpret_cast<const float*>(block.positionsLow.data());
    case PointColumn::Times:
      return block.times.data();
    case PointColumn::Vectors:
      return reinterpret_cast<const float*>(block.vectors.data());
    case PointColumn::Channels:
      return block.channels.data();
    case PointColumn::Vorticity:
      return reinterpret_cast<const float*>(block.vorticity.data());
  }
  return nullptr;
}

// The column's storage in a block, as floats.
float* columnData(RoundBlock& block, PointColumn column) {
  return const_cast<float*>(columnData(std::as_const(block), column));
}

template <typename T>
void release(Column<T>& column) {
  Column<T>().swap(column);
}

}  // namespace

StoredTraces::StoredTraces(TraceSet lines, std::vector<RoundBlock> rounds,
                           std::vector<std::vector<LinePoints>> runs)
    : lines_(std::move(lines)), rounds_(std::move(rounds)) {
  if (runs.size() != rounds_.size())
    throw std::invalid_argument("StoredTraces: one list of runs per round");
  runs_ = LineRuns(lines_.lineCount(), runs);
}

TraceSet StoredTraces::assemble() && {
  TraceSet out = std::move(lines_);
  const std::uint64_t points = out.pointCount();
  const auto gather = [&](auto& target, PointColumn column, auto member) {
    if (!holdsColumn(out, column)) return;
    const std::size_t width = columnWidth(out, column);
    target.resize(points * width / (sizeof(target[0]) / sizeof(float)));
    float* destination = reinterpret_cast<float*>(target.data());
    if (width > 0)
      tbb::parallel_for(std::size_t(0), out.lineCount(), [&](std::size_t line) {
        float* to = destination + out.offsets[line] * width;
        for (const PointRun& run : runs_.of(line)) {
          const float* from = columnData(rounds_[run.round], column) + run.first * width;
          to = std::copy_n(from, std::size_t(run.count) * width, to);
        }
      });
    for (RoundBlock& round : rounds_) release(round.*member);
  };
  gather(out.positions, PointColumn::Positions, &RoundBlock::positions);
  gather(out.positionsLow, PointColumn::PositionsLow, &RoundBlock::positionsLow);
  gather(out.times, PointColumn::Times, &RoundBlock::times);
  gather(out.vectors, PointColumn::Vectors, &RoundBlock::vectors);
  gather(out.channels, PointColumn::Channels, &RoundBlock::channels);
  gather(out.vorticity, PointColumn::Vorticity, &RoundBlock::vorticity);
  rounds_.clear();
  runs_ = LineRuns();
  return out;
}

std::span<const float> StoredTraces::column(PointColumn column, std::size_t line,
                                            std::vector<float>& scratch) const {
  const std::size_t width = columnWidth(lines_, column);
  const std::span<const PointRun> runs = runs_.of(line);
  const std::uint64_t points = runs_.pointCount(line);
  if (points == 0 || width == 0 || !holdsColumn(lines_, column)) return {};
  const auto runValues = [&](const PointRun& run) {
    return columnData(rounds_[run.round], column) + run.first * width;
  };
  const auto nonEmpty = [](const PointRun& run) { return run.count > 0; };
  if (std::count_if(runs.begin(), runs.end(), nonEmpty) == 1)
    return {runValues(*std::find_if(runs.begin(), runs.end(), nonEmpty)), points * width};
  scratch.resize(points * width);
  float* out = scratch.data();
  for (const PointRun& run : runs) out = std::copy_n(runValues(run), run.count * width, out);
  return {scratch.data(), scratch.size()};
}

}  // namespace amrstream::flow
