#include "formats/flash/flash_info.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace amrstream::formats::flash {

namespace {

std::string lowerCase(std::string s) {
  std::ranges::transform(s, s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// Names and values in lower case: FLASH writes parameter names in lower case, values as typed.
std::map<std::string, std::string> stringParameters(const FlashFile& file) {
  std::map<std::string, std::string> parameters;
  for (const auto& [name, value] : file.readPairs<std::string>("string runtime parameters"))
    parameters[lowerCase(name)] = lowerCase(value);
  return parameters;
}

// The units of FLASH's standard variables in its CGS and MKS unit systems (the physics units
// its Config files declare); other variables' are left unknown.
struct StandardUnit {
  const char* name;
  const char* cgs;
  const char* mks;
};
constexpr StandardUnit kStandardUnits[] = {
    {"dens", "g/cm**3", "kg/m**3"},
    {"pres", "erg/cm**3", "Pa"},
    {"temp", "K", "K"},
    {"tele", "K", "K"},
    {"tion", "K", "K"},
    {"trad", "K", "K"},
    {"velx", "cm/s", "m/s"},
    {"vely", "cm/s", "m/s"},
    {"velz", "cm/s", "m/s"},
    {"magx", "gauss", "T"},
    {"magy", "gauss", "T"},
    {"magz", "gauss", "T"},
    {"magp", "erg/cm**3", "Pa"},
    {"ener", "erg/g", "J/kg"},
    {"eint", "erg/g", "J/kg"},
    {"gpot", "erg/g", "J/kg"},
};

}  // namespace

std::optional<double> readFlashTime(const FlashFile& file) {
  std::optional<double> time;
  for (const auto& [name, value] : file.readPairs<double>("real scalars"))
    if (name == "time" && std::isfinite(value)) time = value;
  return time;
}

DatasetInfo readFlashInfo(const FlashFile& file, int finestLeafRefineLevel, int dimensionality,
                          const std::vector<std::string>& variables) {
  DatasetInfo info;
  info.format = "FLASH";
  info.dimensions = dimensionality;
  info.time = readFlashTime(file);

  const auto parameters = stringParameters(file);
  const auto parameter = [&](const std::string& name) -> const std::string* {
    const auto it = parameters.find(name);
    return it == parameters.end() ? nullptr : &it->second;
  };
  // FLASH's pc_unitsBase: lengths in cm or m, times in s either way.
  const std::string* unitsBase = parameter("pc_unitsbase");
  const std::string base = unitsBase == nullptr ? "cgs" : *unitsBase;
  if (base == "cgs" || base == "mks") {
    info.lengthUnit = std::string(base == "cgs" ? "cm" : "m");
    info.lengthUnitCentimetres = base == "cgs" ? 1.0 : 100.0;
    info.timeUnit = std::string("s");
    info.timeUnitSeconds = 1.0;
    for (const StandardUnit& standard : kStandardUnits)
      if (std::ranges::find(variables, standard.name) != variables.end())
        info.units[standard.name] = base == "cgs" ? standard.cgs : standard.mks;
  }

  for (int a = 0; a < std::min(dimensionality, 3); ++a) {
    const std::string axis(1, "xyz"[a]);
    const std::string* lower = parameter(axis + "l_boundary_type");
    const std::string* upper = parameter(axis + "r_boundary_type");
    if (lower != nullptr || upper != nullptr) info.periodicKnown = true;
    info.periodic[a] =
        lower != nullptr && upper != nullptr && *lower == "periodic" && *upper == "periodic";
  }

  info.finestFileLevel = finestLeafRefineLevel;
  info.levelsCountDown = true;
  info.levelName = "FLASH refine level (1 = root)";
  info.rootFileLevel = 1;
  return info;
}

}  // namespace amrstream::formats::flash
