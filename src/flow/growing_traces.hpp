#pragma once
// Traces that grow a frame at a time, as the viewer shows them: streamlines a round at a time
// (ProgressiveTraces) or pathlines through a series of snapshots (api::SeriesPlayback).

#include <cstddef>
#include <cstdint>

#include "trace_set.hpp"

namespace amrstream::flow {

class GrowingTraces {
 public:
  virtual ~GrowingTraces() = default;
  // Advances the running lines by up to `steps` steps each; returns the particle-steps taken.
  virtual std::size_t advance(std::uint32_t steps) = 0;
  virtual bool finished() const = 0;
  virtual std::size_t runningCount() const = 0;
  virtual std::size_t lineCount() const = 0;
  virtual std::size_t stepsTaken() const = 0;
  // The lines so far; reasons are AMRSTREAM_REASON_RUNNING until a line ends.
  virtual const TraceSet& traces() const = 0;
  // The lines the last advance() moved, each with the points it added and, before them, its
  // last point from before (when it had one and the advance added any): the polylines that
  // extend the traces.
  virtual const TraceSet& recent() const = 0;
};

}  // namespace amrstream::flow
