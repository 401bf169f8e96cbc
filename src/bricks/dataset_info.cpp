#include "amrstream/dataset_info.hpp"

#include <fmt/format.h>

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

}  // namespace amrstream
