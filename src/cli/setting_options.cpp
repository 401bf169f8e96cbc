#include "setting_options.hpp"

namespace amrstream::cli {

std::string settingHelp(const Setting& setting) { return spellSettings(setting.help, cliFlag); }

}  // namespace amrstream::cli
