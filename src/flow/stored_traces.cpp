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
  const std::size_t lineCount = lines_.lineCount();
  std::vector<std::uint64_t> counts(lineCount + 1, 0);
  for (const std::vector<LinePoints>& round : runs)
    for (const LinePoints& r : round) {
      if (r.line >= lineCount) throw std::invalid_argument("StoredTraces: no such line");
      ++counts[r.line + 1];
    }
  for (std::size_t i = 0; i < lineCount; ++i) counts[i + 1] += counts[i];
  runOffsets_ = counts;
  runs_.resize(counts.back());
  // Each round's list is released once placed: the peak holds the lists and the runs once.
  for (std::uint32_t round = 0; round < rounds_.size(); ++round) {
    std::uint32_t first = 0;
    for (const LinePoints& r : runs[round]) {
      runs_[counts[r.line]++] = {round, r.points, first};
      first += r.points;
    }
    std::vector<LinePoints>().swap(runs[round]);
  }
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
        for (std::uint64_t r = runOffsets_[line]; r < runOffsets_[line + 1]; ++r) {
          const Run& run = runs_[r];
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
  runs_.clear();
  runOffsets_.assign(1, 0);
  return out;
}

std::span<const float> StoredTraces::column(PointColumn column, std::size_t line,
                                            std::vector<float>& scratch) const {
  const std::size_t width = columnWidth(lines_, column);
  const std::uint64_t begin = runOffsets_[line], end = runOffsets_[line + 1];
  std::uint64_t points = 0;
  for (std::uint64_t r = begin; r < end; ++r) points += runs_[r].count;
  if (points == 0 || width == 0 || !holdsColumn(lines_, column)) return {};
  const auto runValues = [&](const Run& run) {
    return columnData(rounds_[run.round], column) + run.first * width;
  };
  std::uint64_t nonEmpty = 0, only = begin;
  for (std::uint64_t r = begin; r < end; ++r)
    if (runs_[r].count > 0) ++nonEmpty, only = r;
  if (nonEmpty == 1) return {runValues(runs_[only]), points * width};
  scratch.resize(points * width);
  float* out = scratch.data();
  for (std::uint64_t r = begin; r < end; ++r) {
    out = std::copy_n(runValues(runs_[r]), runs_[r].count * width, out);
  }
  return {scratch.data(), scratch.size()};
}

}  // namespace amrstream::flow
