// Traces a rake of seeds through a built-in dataset with an installed amrstream and checks the
// lines: two a seed (both directions), each starting at its seed.
#include <cstdio>

#include "amrstream/distributed.hpp"
#include "amrstream/trace_job.hpp"

int main() {
  amrstream::TraceJob job;
  job.dataset = {"builtin:rotation", {2, 2, 20000, 1, 0.0}};
  job.seeds.line = {0.3, 0.5, 0.5, 0.4, 0.5, 0.5};
  job.seeds.count = 3;
  job.trace.steps = 20;
  job.backend.backend = "cpu";
  amrstream::PreparedJob prepared = amrstream::prepare(job);
  const amrstream::Traces traces = amrstream::trace(prepared).assemble();
  if (traces.lineCount() != 6) return 1;
  for (std::size_t line = 0; line < traces.lineCount(); ++line) {
    const glm::dvec3 start = traces.point(traces.offsets()[line]);
    const glm::dvec3 seed = prepared.seeds()[traces.seedIds()[line]];
    if (glm::length(start - seed) > 1e-6) return 2;
  }
  const amrstream::MpiWorld world;  // not started by mpirun: a world of one
  if (world.size() != 1) return 3;
  amrstream::checkDistributedTrace(job, {});
  std::printf("consumer: %zu lines of %llu points from an installed amrstream\n",
              traces.lineCount(), static_cast<unsigned long long>(traces.pointCount()));
  return 0;
}
