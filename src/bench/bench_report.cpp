#include "bench_report.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <span>

#include "output/atomic_file.hpp"

namespace amrstream::bench {

namespace {

double mib(std::uint64_t bytes) { return double(bytes) / 0x1p20; }

nlohmann::json optionalNumber(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

const char* modeName(bool history) { return history ? "history" : "endpoints"; }

nlohmann::json toJson(const BenchRow& r) {
  return {{"backend", r.backend},
          {"device", r.device},
          {"mode", modeName(r.history)},
          {"particles", r.particles},
          {"max_steps", r.maxSteps},
          {"steps", r.steps},
          {"kernel_seconds", optionalNumber(r.kernelSeconds)},
          {"compaction_seconds", optionalNumber(r.compactionSeconds)},
          {"wall_seconds", r.wallSeconds},
          {"steps_per_second", r.stepsPerSecond()},
          {"wall_steps_per_second", r.wallStepsPerSecond()},
          {"device_bytes", r.deviceBytes},
          {"chunks", r.chunks},
          {"rounds", r.rounds},
          {"cpu_tail_lines", r.tailLines},
          {"cpu_tail_steps", r.tailSteps},
          {"cpu_tail_seconds", r.tailSeconds}};
}

nlohmann::json toJson(const BackendSetup& s) {
  return {{"backend", s.backend},
          {"device", s.device},
          {"driver", s.driver},
          {"context_seconds", s.contextSeconds},
          {"upload_seconds", s.uploadSeconds},
          {"structure_seconds", s.structureSeconds},
          {"pipeline_seconds", s.pipelineSeconds},
          {"region_hint", s.regionHint},
          {"dual_values", s.dualValues},
          {"spread_threads", s.spreadThreads},
          {"volume_bytes", s.volumeBytes},
          {"structure_bytes", s.structureBytes}};
}

nlohmann::json toJson(const DatasetStats& d) {
  return {{"source", d.source},
          {"cells", d.cells},
          {"levels", d.coarsestLevel - d.finestLevel + 1},
          {"vector", d.vector},
          {"load_seconds", d.loadSeconds},
          {"bricks", d.bricks},
          {"regions", d.regions},
          {"bricks_seconds", d.bricksSeconds},
          {"regions_seconds", d.regionsSeconds},
          {"gather_seconds", d.gatherSeconds},
          {"seeding", d.seeding}};
}

nlohmann::json toJson(const BenchConfig& c) {
  nlohmann::json modes = nlohmann::json::array();
  for (const bool history : c.historyModes) modes.push_back(modeName(history));
  const char* stepMode = c.trace.stepMode == flow::StepMode::Time  ? "time"
                         : c.trace.stepMode == flow::StepMode::Arc ? "arc"
                                                                   : "cell";
  return {{"backends", c.backends},
          {"particles", c.particles},
          {"cpu_max_particles", c.cpuMaxParticles},
          {"modes", modes},
          {"history_point_budget", c.historyPointBudget},
          {"repeats", c.repeats},
          {"steps", c.trace.maxSteps},
          {"round_steps", c.trace.roundSteps},
          {"cpu_tail_lines", c.trace.cpuTailLines},
          {"step_mode", stepMode},
          {"step_size", c.trace.stepSize},
          {"region_hint", c.regionHint ? nlohmann::json(*c.regionHint) : nlohmann::json("default")},
          {"dual_values", c.dualValues ? nlohmann::json(*c.dualValues) : nlohmann::json("default")},
          {"spread_threads",
           c.spreadThreads ? nlohmann::json(*c.spreadThreads) : nlohmann::json("default")},
          {"seed_order", c.spatialSeedOrder ? "spatial" : "given"},
          {"validation", c.validation}};
}

}  // namespace

std::string tableHeader() {
  return fmt::format("{:<9} {:<9} {:>9} {:>13} {:>10} {:>10} {:>12} {:>12} {:>10}\n", "backend",
                     "mode", "particles", "steps", "kernel s", "wall s", "steps/s", "wall st/s",
                     "dev MiB");
}

std::string tableRow(const BenchRow& r) {
  const std::string kernel = r.kernelSeconds ? fmt::format("{:.4f}", *r.kernelSeconds) : "-";
  const std::string memory = r.deviceBytes ? fmt::format("{:.1f}", mib(r.deviceBytes)) : "-";
  std::string row =
      fmt::format("{:<9} {:<9} {:>9} {:>13} {:>10} {:>10.4f} {:>12.3e} {:>12.3e} {:>10}\n",
                  r.backend, modeName(r.history), r.particles, r.steps, kernel, r.wallSeconds,
                  r.stepsPerSecond(), r.wallStepsPerSecond(), memory);
  if (r.tailLines > 0)
    row += fmt::format("  the CPU finished {} line{}: {} steps in {:.4f} s (steps/s by wall)\n",
                       r.tailLines, r.tailLines == 1 ? "" : "s", r.tailSteps, r.tailSeconds);
  return row;
}

std::string setupLine(const BackendSetup& s) {
  return fmt::format(
      "{:<9} on {} ({}): context {:.2f} s, upload {:.2f} s ({:.1f} MiB), structure {:.2f} s "
      "({:.1f} MiB), pipeline {:.2f} s; region hint {}, dual values {}, spread below {} "
      "threads\n",
      s.backend, s.device, s.driver, s.contextSeconds, s.uploadSeconds, mib(s.volumeBytes),
      s.structureSeconds, mib(s.structureBytes), s.pipelineSeconds, s.regionHint ? "on" : "off",
      s.dualValues ? "on" : "off", s.spreadThreads);
}

void writeJson(const std::filesystem::path& path, const BenchReport& report) {
  nlohmann::json doc;
  doc["command"] = report.command;
  doc["host"] = report.host;
  doc["ranks"] = report.ranks;
  doc["dataset"] = toJson(report.dataset);
  doc["config"] = toJson(report.config);
  doc["setups"] = nlohmann::json::array();
  for (const BackendSetup& s : report.setups) doc["setups"].push_back(toJson(s));
  doc["rows"] = nlohmann::json::array();
  for (const BenchRow& r : report.rows) doc["rows"].push_back(toJson(r));
  doc["notes"] = report.notes;
  const std::string text = doc.dump(2) + "\n";
  output::AtomicFile file(path);
  file.write(std::as_bytes(std::span(text.data(), text.size())));
  file.commit();
}

}  // namespace amrstream::bench
