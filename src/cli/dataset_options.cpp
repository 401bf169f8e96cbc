#include "dataset_options.hpp"

#include <limits>

#include "option_checks.hpp"
#include "setting_options.hpp"

namespace amrstream::cli {

void addGeneratorOptions(CLI::App& command, BuiltinOptions& options, const std::string& seedFlag,
                         int maxLevels) {
  command
      .add_option(cliFlag(settings::kLevels.name), options.levels, settingHelp(settings::kLevels))
      ->default_str(shownDefault(settings::kLevels))
      ->check(countIn(1, maxLevels));
  addSetting(command, settings::kRootBlocks, options.rootBlocks);
  addSetting(command, settings::kTargetCells, options.targetCells);
  command.add_option(seedFlag, options.seed, settingHelp(settings::kGenSeed))
      ->default_str(shownDefault(settings::kGenSeed))
      ->check(*settingCheck<std::uint64_t>(settings::kGenSeed));
  addSetting(command, settings::kTime, options.time);
}

void addDatasetOptions(CLI::App& command, DatasetRequest& options, const std::string& seedFlag,
                       DeclaresUnits units) {
  std::string kinds;
  for (const std::string& kind : builtinKinds()) kinds += (kinds.empty() ? "" : "|") + kind;
  command
      .add_option("input", options.input,
                  "the dataset: a FLASH HDF5 plotfile or checkpoint, an Enzo parameter file (or "
                  "its .hierarchy, .harrays or .cpuNNNN), an AMReX plotfile directory, a Gerris "
                  "text dump, an ExaBricks .exa file, or builtin:" +
                      kinds)
      ->required();
  addGeneratorOptions(command, options.builtin, seedFlag, kMaxBuiltinLevels);
  if (units == DeclaresUnits::Yes) addUnitOptions(command, options.units);
}

void addUnitOptions(CLI::App& command, DeclaredUnits& units) {
  addSetting(command, settings::kLengthUnit, units.length);
  addSetting(command, settings::kUnit, units.units)
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace amrstream::cli
