#pragma once
// Whether the traces of a request fit in host memory, judged before tracing: a request that
// cannot fit fails at once, naming the figure, instead of after minutes of tracing with the
// machine's memory nearly full.

#include <cstdint>
#include <glm/glm.hpp>
#include <span>

#include "flow/trace_options.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

// The host memory traces may take now: 3/4 of the machine's, less what the process holds
// already (the dataset, the volume), and at least 1/16 of the machine's.
std::uint64_t hostTraceLimit();

// InputError ("traces") when the lines of `seeds` cannot fit options.maxResultBytes: their
// bookkeeping (flow::kHeldBytesPerLine) alone, or, where every line's maxSteps + 1 points could not
// fit, the points a sample of the seeds traced on the CPU averages (a sampled line still running
// after its sample's steps counts as running to maxSteps).
void checkHostTracesFit(const flow::VectorVolume& volume, std::span<const glm::dvec3> seeds,
                        const flow::TraceOptions& options);

}  // namespace amrstream
