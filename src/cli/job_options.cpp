#include "job_options.hpp"

#include "amrstream/settings.hpp"
#include "amrstream/trace_settings.hpp"
#include "dataset_options.hpp"
#include "option_checks.hpp"
#include "setting_options.hpp"

namespace amrstream::cli {

namespace s = settings;

namespace {

constexpr const char* kSeedsGroup = "Seeds";
constexpr const char* kTracingGroup = "Tracing";

}  // namespace

void addSeedOptions(CLI::App& command, SeedRequest& seeds, std::string* seedsOut) {
  const auto seedOption = [&](const Setting& setting, auto& value) {
    return addSetting(command, setting, value)->group(kSeedsGroup);
  };
  auto* seedsFile = seedOption(s::kSeeds, seeds.file)->check(regularFile());
  seedOption(s::kSeedBox, seeds.box)->delimiter(',')->expected(6)->excludes(seedsFile);
  auto* seedLine =
      seedOption(s::kSeedLine, seeds.line)->delimiter(',')->expected(6)->excludes(seedsFile);
  auto* seedGrid = seedOption(s::kSeedGrid, seeds.grid)
                       ->delimiter(',')
                       ->expected(3)
                       ->excludes(seedsFile)
                       ->excludes(seedLine);
  auto* seedDensity =
      seedOption(s::kSeedDensity, seeds.density)->excludes(seedsFile)->excludes(seedLine);
  seedOption(s::kSeedPercentile, seeds.percentile)->needs(seedDensity);
  seedOption(s::kSeedWeighted, seeds.weighted)->needs(seedDensity);
  if (seedsOut != nullptr) seedOption(s::kSeedsOut, *seedsOut);
  seedOption(s::kCount, seeds.count)->excludes(seedsFile)->excludes(seedGrid);
  seedOption(s::kSeed, seeds.seed)->excludes(seedsFile);
}

void addFieldOptions(CLI::App& command, FieldOptions& field) {
  addSetting(command, s::kVector, field.vector);
  addSetting(command, s::kPointData, field.pointData);
  addSetting(command, s::kPeriodic, field.periodic);
  addSetting(command, s::kInterpolant, field.interpolant);
}

void addFrameVelocityOption(CLI::App& command, FieldOptions& field) {
  addSetting(command, s::kFrameVelocity, field.frameVelocity);
}

void addBackendOptions(CLI::App& command, BackendRequest& backend) {
  addSetting(command, s::kBackend, backend.backend);
  addSetting(command, s::kDevice, backend.device);
}

void addTraceJobOptions(CLI::App& command, TraceJob& job, std::size_t defaultCount) {
  job.seeds.count = defaultCount;
  addDatasetOptions(command, job.dataset, "--gen-seed");
  addFieldOptions(command, job.field);
  addFrameVelocityOption(command, job.field);
  addSeedOptions(command, job.seeds, &job.seedsOut);
  TraceSettings& t = job.trace;
  const auto stepping = [&](const Setting& setting, auto& value) {
    addSetting(command, setting, value)->group(kTracingGroup);
  };
  stepping(s::kSteps, t.steps);
  stepping(s::kStepSize, t.stepSize);
  stepping(s::kStepMode, t.stepMode);
  stepping(s::kIntegrator, t.integrator);
  stepping(s::kTolerance, t.tolerance);
  stepping(s::kMinStep, t.minStep);
  stepping(s::kMaxStep, t.maxStep);
  stepping(s::kDirection, t.direction);
  stepping(s::kVorticity, t.vorticity);
  stepping(s::kTerminalSpeed, t.terminalSpeed);
  stepping(s::kMaxLength, t.maxLength);
  stepping(s::kMaxTime, t.maxTime);
  // Sizes such as 512M, up to the machine's memory.
  command.add_option(cliFlag(s::kMemoryBudget.name), t.memoryBudget, settingHelp(s::kMemoryBudget))
      ->transform(CLI::AsSizeValue(false))
      ->check(countIn(0, maxMemoryBudget()))
      ->default_str(shownDefault(s::kMemoryBudget))
      ->group(kTracingGroup);
  stepping(s::kCpuTail, t.cpuTail);
  addBackendOptions(command, job.backend);
}

std::vector<std::string> givenTracingOptions(const CLI::App& command) {
  std::vector<std::string> given;
  for (const CLI::Option* option : command.get_options())
    if (option->count() > 0 &&
        (option->get_group() == kSeedsGroup || option->get_group() == kTracingGroup))
      given.push_back(option->get_name());
  return given;
}

}  // namespace amrstream::cli
