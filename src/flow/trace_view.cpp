#include "trace_view.hpp"

namespace amrstream::flow {

std::size_t columnWidth(const TraceSet& lines, PointColumn column) {
  switch (column) {
    case PointColumn::Times:
      return 1;
    case PointColumn::Channels:
      return lines.channelCount();
    case PointColumn::Positions:
    case PointColumn::PositionsLow:
    case PointColumn::Vectors:
    case PointColumn::Vorticity:
      break;
  }
  return 3;
}

bool holdsColumn(const TraceSet& lines, PointColumn column) {
  switch (column) {
    case PointColumn::PositionsLow:
      return lines.precisePositions;
    case PointColumn::Vorticity:
      return lines.withVorticity;
    case PointColumn::Positions:
    case PointColumn::Times:
    case PointColumn::Vectors:
    case PointColumn::Channels:
      break;
  }
  return true;
}

std::span<const float> TraceSetView::column(PointColumn column, std::size_t line,
                                            std::vector<float>&) const {
  const TraceSet& t = *traces_;
  const std::size_t width = columnWidth(t, column);
  const std::uint64_t first = t.offsets[line] * width, count = t.pointCount(line) * width;
  if (count == 0 || !holdsColumn(t, column)) return {};
  const float* data = nullptr;
  switch (column) {
    case PointColumn::Positions:
      data = &t.positions.data()->x;
      break;
    case PointColumn::PositionsLow:
      data = &t.positionsLow.data()->x;
      break;
    case PointColumn::Times:
      data = t.times.data();
      break;
    case PointColumn::Vectors:
      data = &t.vectors.data()->x;
      break;
    case PointColumn::Channels:
      data = t.channels.data();
      break;
    case PointColumn::Vorticity:
      data = &t.vorticity.data()->x;
      break;
  }
  return {data + first, count};
}

std::span<const double> exactPositions(const TraceView& traces, std::size_t line,
                                       std::vector<double>& scratch) {
  std::vector<float> highScratch, lowScratch;
  const std::span<const float> high = traces.column(PointColumn::Positions, line, highScratch);
  const std::span<const float> low = traces.column(PointColumn::PositionsLow, line, lowScratch);
  scratch.resize(high.size());
  for (std::size_t k = 0; k < high.size(); k += 3) {
    const glm::vec3 highPart(high[k], high[k + 1], high[k + 2]);
    const glm::dvec3 p = low.empty() ? glm::dvec3(highPart)
                                     : joinPosition(highPart, {low[k], low[k + 1], low[k + 2]});
    scratch[k] = p.x, scratch[k + 1] = p.y, scratch[k + 2] = p.z;
  }
  return scratch;
}

}  // namespace amrstream::flow
