#pragma once
// What every generated dataset says about itself: format "builtin", the snapshot's time, units
// unknown (dimensionless), its periodic axes, and levels numbered from the coarsest (0) to the
// finest possible one (levels - 1).

#include "amrstream/dataset_info.hpp"

namespace amrstream::synth {

inline DatasetInfo builtinInfo(int levels, double time, bool periodic) {
  DatasetInfo info;
  info.format = "builtin";
  info.time = time;
  info.periodic = {periodic, periodic, periodic};
  info.periodicKnown = true;
  info.finestFileLevel = levels - 1;
  info.levelsCountDown = true;
  info.levelName = "builtin level (0 = coarsest)";
  return info;
}

}  // namespace amrstream::synth
