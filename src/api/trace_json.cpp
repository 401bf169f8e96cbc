#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <string>

#include "amrstream/trace_job.hpp"
#include "output/atomic_file.hpp"

namespace amrstream {

void writeTraceJson(const std::filesystem::path& path, const TraceJobSummary& summary,
                    const StageClock& clock) {
  const TraceReport& r = summary.report;
  nlohmann::json stages = nlohmann::json::array();
  for (const StageClock::Stage& stage : clock.stages())
    stages.push_back({{"name", stage.name}, {"seconds", stage.seconds}});
  const nlohmann::json doc = {{"command", "trace"},
                              {"input", summary.input},
                              {"cells", summary.cells},
                              {"seeds", summary.seeds},
                              {"lines", summary.lines},
                              {"steps", summary.steps},
                              {"points_written", summary.pointsWritten},
                              {"backend", r.backend},
                              {"device", r.device},
                              {"trace_seconds", r.traceSeconds},
                              {"particle_steps_per_second",
                               r.traceSeconds > 0.0 ? double(summary.steps) / r.traceSeconds : 0.0},
                              {"device_setup",
                               {{"backend_choice_seconds", r.chooseSeconds},
                                {"seconds", r.setupSeconds},
                                {"upload_seconds", r.uploadSeconds},
                                {"structure_seconds", r.structureSeconds},
                                {"kernel_seconds", r.kernelSeconds},
                                {"dual_cells", r.dualCells}}},
                              {"wall_seconds", clock.wallSeconds()},
                              {"stages", stages}};
  const std::string text = doc.dump(2) + "\n";
  output::AtomicFile file(path);
  file.write(std::as_bytes(std::span(text)));
  file.commit();
}

}  // namespace amrstream
