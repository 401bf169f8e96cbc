#include "api/declared_units.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "amrstream/closest_name.hpp"
#include "amrstream/error.hpp"

namespace amrstream {

void declareInputUnits(bricks::AmrField& cells, const DeclaredUnits& declared,
                       const std::vector<std::string>& names) {
  if (declared.empty()) return;
  DatasetInfo info = cells.info();
  declareUnits(info, declared, cells.source());
  for (const std::string& entry : declared.units) {
    const std::string name = entry.substr(0, entry.find('='));
    if (std::ranges::find(names, name) != names.end()) continue;
    std::string list;
    for (const std::string& known : names) list += (list.empty() ? "" : ", ") + known;
    throw settingError("unit",
                       fmt::format("'{}' is no channel or vector of {}{}; the names are: {}", name,
                                   cells.source(), didYouMean(name, names), list));
  }
  cells.setInfo(std::move(info));
}

}  // namespace amrstream
