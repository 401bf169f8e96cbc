#include "job_options.hpp"

#include "amrstream/settings.hpp"
#include "amrstream/trace_settings.hpp"
#include "dataset_options.hpp"
#include "option_checks.hpp"
#include "setting_options.hpp"

namespace amrstream::cli {

namespace s = settings;

void addSeedOptions(CLI::App& command, SeedRequest& seeds, std::string* seedsOut) {
  auto* seedsFile = addSetting(command, s::kSeeds, seeds.file)->check(regularFile());
  addSetting(command, s::kSeedBox, seeds.box)->delimiter(',')->expected(6)->excludes(seedsFile);
  auto* seedLine = addSetting(command, s::kSeedLine, seeds.line)
                       ->delimiter(',')
                       ->expected(6)
                       ->excludes(seedsFile);
  auto* seedGrid = addSetting(command, s::kSeedGrid, seeds.grid)
                       ->delimiter(',')
                       ->expected(3)
                       ->excludes(seedsFile)
                       ->excludes(seedLine);
  auto* seedDensity =
      addSetting(command, s::kSeedDensity, seeds.density)->excludes(seedsFile)->excludes(seedLine);
  addSetting(command, s::kSeedPercentile, seeds.percentile)->needs(seedDensity);
  addSetting(command, s::kSeedWeighted, seeds.weighted)->needs(seedDensity);
  if (seedsOut != nullptr) addSetting(command, s::kSeedsOut, *seedsOut);
  addSetting(command, s::kCount, seeds.count)->excludes(seedsFile)->excludes(seedGrid);
  addSetting(command, s::kSeed, seeds.seed)->excludes(seedsFile);
}

void addFieldOptions(CLI::App& command, FieldOptions& field) {
  addSetting(command, s::kVector, field.vector);
  addSetting(command, s::kPointData, field.pointData);
  addSetting(command, s::kPeriodic, field.periodic);
  addSetting(command, s::kInterpolant, field.interpolant);
}

void addBackendOptions(CLI::App& command, BackendRequest& backend) {
  addSetting(command, s::kBackend, backend.backend);
  addSetting(command, s::kDevice, backend.device);
}

void addTraceJobOptions(CLI::App& command, TraceJob& job, std::size_t defaultCount) {
  job.seeds.count = defaultCount;
  addDatasetOptions(command, job.dataset, "--gen-seed");
  addFieldOptions(command, job.field);
  addSeedOptions(command, job.seeds, &job.seedsOut);
  TraceSettings& t = job.trace;
  addSetting(command, s::kSteps, t.steps);
  addSetting(command, s::kStepSize, t.stepSize);
  addSetting(command, s::kStepMode, t.stepMode);
  addSetting(command, s::kIntegrator, t.integrator);
  addSetting(command, s::kTolerance, t.tolerance);
  addSetting(command, s::kMinStep, t.minStep);
  addSetting(command, s::kMaxStep, t.maxStep);
  addSetting(command, s::kDirection, t.direction);
  addSetting(command, s::kVorticity, t.vorticity);
  addSetting(command, s::kTerminalSpeed, t.terminalSpeed);
  addSetting(command, s::kMaxLength, t.maxLength);
  addSetting(command, s::kMaxTime, t.maxTime);
  // Sizes such as 512M, up to the machine's memory.
  command.add_option(cliFlag(s::kMemoryBudget.name), t.memoryBudget, settingHelp(s::kMemoryBudget))
      ->transform(CLI::AsSizeValue(false))
      ->check(countIn(0, maxMemoryBudget()))
      ->default_str(shownDefault(s::kMemoryBudget));
  addSetting(command, s::kCpuTail, t.cpuTail);
  addBackendOptions(command, job.backend);
}

}  // namespace amrstream::cli
