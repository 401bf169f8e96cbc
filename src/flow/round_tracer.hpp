#pragma once
// A trace in progress: lines that advance round by round. Every tracer (the CPU reference and
// each GPU backend) runs its lines this way; the viewer advances one round per frame.

#include <cstdint>
#include <memory>
#include <vector>

#include "../../shaders/glsl/shared/line_state.h"
#include "round_block.hpp"
#include "trace_options.hpp"
#include "vector_volume.hpp"

namespace amrstream::flow {

class RoundTracer {
 public:
  virtual ~RoundTracer() = default;
  // Lines that have not ended.
  virtual std::size_t liveLines() const = 0;
  // Advances every live line by at most `steps` steps (0 is taken as 1); lines that end report
  // their reason in the block and take no part in later rounds.
  virtual RoundBlock advance(std::uint32_t steps) = 0;
  // The live lines' states, from which a tracer made of them would go on as this one does (MPI
  // ranks hand lines on between rounds). Between rounds only.
  virtual std::vector<shared::LineState> liveStates() const = 0;
};

// The CPU reference, on all cores. `volume` must outlive it.
std::unique_ptr<RoundTracer> cpuRoundTracer(const VectorVolume& volume,
                                            std::span<const shared::LineState> lines,
                                            const TraceOptions& options);

}  // namespace amrstream::flow
