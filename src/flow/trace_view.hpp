#pragma once
// Read access to traces one line and one column at a time, whether their points are stored line
// after line (a TraceSet) or round after round as the tracers produce them (the accumulator's
// StoredTraces): writers need no assembled copy of a large result.

#include <cstddef>
#include <span>
#include <vector>

#include "trace_set.hpp"

namespace amrstream::flow {

enum class PointColumn { Positions, PositionsLow, Times, Vectors, Channels, Vorticity };

// Floats per point of a column: 3, 3, 1, 3, the channel count, 3.
std::size_t columnWidth(const TraceSet& lines, PointColumn column);
// Whether the traces hold the column: PositionsLow only with precisePositions, Vorticity only
// withVorticity. A column they do not hold reads as empty.
bool holdsColumn(const TraceSet& lines, PointColumn column);

class TraceView {
 public:
  virtual ~TraceView() = default;
  // The lines (seed ids, directions, steps, reasons, offsets) and names; the point columns of
  // this TraceSet may be empty: read points through column().
  virtual const TraceSet& lines() const = 0;
  // The values of `column` along `line`, columnWidth() floats per point, contiguous: a view of
  // the storage, or a copy made in `scratch`. Valid until the next call with the same scratch.
  virtual std::span<const float> column(PointColumn column, std::size_t line,
                                        std::vector<float>& scratch) const = 0;
};

// The positions along `line`, x, y, z per point: joinPosition of the two columns when the traces
// are precise, else the stored floats. Valid until the next call with the same scratch.
std::span<const double> exactPositions(const TraceView& traces, std::size_t line,
                                       std::vector<double>& scratch);

// A TraceSet as a TraceView, without copies. The TraceSet must outlive it.
class TraceSetView final : public TraceView {
 public:
  explicit TraceSetView(const TraceSet& traces) : traces_(&traces) {}
  const TraceSet& lines() const override { return *traces_; }
  std::span<const float> column(PointColumn column, std::size_t line,
                                std::vector<float>& scratch) const override;

 private:
  const TraceSet* traces_;
};

}  // namespace amrstream::flow
