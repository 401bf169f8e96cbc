#include "amrstream/dataset_info.hpp"

#include <fmt/format.h>

#include "amrstream/error.hpp"

namespace amrstream {

int DatasetInfo::fileLevel(int internalLevel) const {
  if (!fileLevelOfInternal.empty())
    return internalLevel >= 0 && internalLevel < int(fileLevelOfInternal.size())
               ? fileLevelOfInternal[std::size_t(internalLevel)]
               : -1;
  return levelsCountDown ? finestFileLevel - internalLevel : finestFileLevel + internalLevel;
}

std::string timeAndUnitsClause(const DatasetInfo& info) {
  std::string clause;
  if (info.time)
    clause += fmt::format(", t = {:.9g}{}{}", *info.time, info.timeUnit.empty() ? "" : " ",
                          info.timeUnit);
  if (!info.lengthUnit.empty()) clause += ", lengths in " + info.lengthUnit;
  return clause;
}

std::string periodicAxesText(const DatasetInfo& info) {
  if (!info.periodicKnown) return "unknown";
  std::string axes;
  for (int a = 0; a < 3; ++a)
    if (info.periodic[a]) axes += std::string(axes.empty() ? "" : " ") + "xyz"[a];
  return axes.empty() ? "none" : axes;
}

std::string unitOf(const DatasetInfo& info, std::string_view name) {
  const auto found = info.units.find(name);
  return found == info.units.end() ? std::string() : found->second;
}

namespace {

// The file's unit, or the one declared where it states none; a differing one is refused.
void declareOne(std::string& stated, const std::string& declared, const char* setting,
                const std::string& what, const std::string& source) {
  if (declared.empty() || declared == stated) return;
  if (!stated.empty())
    throw settingError(setting, fmt::format("{} states {} in {}; a unit the file states cannot be "
                                            "changed",
                                            source, what, stated));
  stated = declared;
}

}  // namespace

void declareUnits(DatasetInfo& info, const DeclaredUnits& declared, const std::string& source) {
  if (declared.length.find_first_not_of(" \t") == std::string::npos && !declared.length.empty())
    throw settingError("length_unit", "give a unit such as cm, m, kpc or Mpc");
  declareOne(info.lengthUnit, declared.length, "length_unit", "its lengths", source);
  for (const std::string& entry : declared.units) {
    const std::size_t equals = entry.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == entry.size())
      throw settingError("unit",
                         fmt::format("'{}': expected NAME=UNIT, e.g. density=g/cm**3", entry));
    const std::string name = entry.substr(0, equals);
    std::string& unit = info.units[name];
    declareOne(unit, entry.substr(equals + 1), "unit", fmt::format("the unit of {}", name), source);
  }
}

}  // namespace amrstream
