#include "trace_view.hpp"

namespace amrstream::flow {

std::size_t columnWidth(const TraceSet& lines, PointColumn column) {
  switch (column) {
    case PointColumn::Times:
      return 1;
    case PointColumn::Channels:
      return lines.channelCount();
    case PointColumn::Positions:
    case PointColumn::Vectors:
    case PointColumn::Vorticity:
      break;
  }
  return 3;
}

std::span<const float> TraceSetView::column(PointColumn column, std::size_t line,
                                            std::vector<float>&) const {
  const TraceSet& t = *traces_;
  const std::size_t width = columnWidth(t, column);
  const std::uint64_t first = t.offsets[line] * width, count = t.pointCount(line) * width;
  if (count == 0) return {};
  const float* data = nullptr;
  switch (column) {
    case PointColumn::Positions:
      data = &t.positions.data()->x;
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

}  // namespace amrstream::flow
