#pragma once
// VolumeOptions with one field set (a designated initializer that leaves the others out draws
// -Wmissing-field-initializers).

#include <string>
#include <utility>
#include <vector>

#include "flow/vector_volume.hpp"

namespace amrstream::testing {

inline flow::VolumeOptions periodicVolume(flow::PeriodicAxes axes) {
  flow::VolumeOptions options;
  options.periodic = axes;
  return options;
}

inline flow::VolumeOptions withPointData(std::vector<std::string> channels) {
  flow::VolumeOptions options;
  options.pointData = std::move(channels);
  return options;
}

}  // namespace amrstream::testing
