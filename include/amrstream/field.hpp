#pragma once
// A dataset made ready for tracing: the vector and point-data channels chosen, periodic images
// added, bricks and active brick regions built (flow::VectorVolume).

#include <string>

#include "amrstream/dataset.hpp"
#include "flow/vector_selection.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

struct FieldOptions {
  std::string vector;                // "a,b,c"; empty: the velocity, else the magnetic field
  std::string pointData = "all";     // all (every channel but the vector's), none, or NAME,NAME,...
  std::string periodic = "auto";     // auto (as the file says), none, or axes such as "x,y,z"
  std::string interpolant = "tent";  // tent (the paper's) or linear (exact for linear fields)
};

struct Field {
  flow::VectorVolume volume;
  flow::VectorChannels vector;
  std::string source;        // the dataset's name
  bricks::DatasetInfo info;  // what the dataset says of itself
  flow::VolumeBuildTimes times;
};

// Throws InputError naming the missing channel or the bad option.
Field buildField(const Dataset& cells, const FieldOptions& options);

// What buildField builds from a dataset's channel names and what it says of itself: the vector,
// and the volume's options (periodic axes, point data, interpolant). For a volume built in two
// steps, its layout before the values (flow::buildCellLayout, then flow::fillVolumeValues).
struct FieldPlan {
  flow::VectorChannels vector;
  flow::VolumeOptions volume;
};
FieldPlan planField(const flow::ChannelCatalog& channels, const bricks::DatasetInfo& info,
                    const FieldOptions& options);

// "auto", "none", or the periodic axes, e.g. "x,y,z" or "xz".
flow::PeriodicAxes periodicAxes(const std::string& request, const bricks::DatasetInfo& info);
std::string axesText(const flow::PeriodicAxes& axes);  // "x,z"; empty for none

// "tent" or "linear"; InputError otherwise.
flow::Interpolant parseInterpolant(const std::string& name);
std::string interpolantName(flow::Interpolant interpolant);

}  // namespace amrstream
