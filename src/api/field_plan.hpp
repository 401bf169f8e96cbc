#pragma once
// What a Field is built from: the vector, the point-data channels, the periodic axes and the
// interpolant that the field options name, resolved against a dataset's channels and what it
// says of itself. For a volume built in two steps, its layout before the values
// (flow::buildCellLayout, then flow::fillVolumeValues).

#include <string>

#include "amrstream/dataset_info.hpp"
#include "amrstream/field.hpp"
#include "api/frame_choice.hpp"
#include "flow/vector_selection.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

// For frame_velocity auto, volume.autoFrame is set by the builder, which knows the region.
struct FieldPlan {
  flow::VectorChannels vector;  // with the frame velocity when given
  flow::VolumeOptions volume;
  FrameChoice frame;
};
FieldPlan planField(const flow::ChannelCatalog& channels, const DatasetInfo& info,
                    const FieldOptions& options);

// "auto", "none", or the periodic axes, e.g. "x,y,z" or "xz".
flow::PeriodicAxes periodicAxes(const std::string& request, const DatasetInfo& info);
std::string axesText(const flow::PeriodicAxes& axes);  // "x,z"; empty for none

// "tent" or "linear"; InputError otherwise.
flow::Interpolant parseInterpolant(const std::string& name);
std::string interpolantName(flow::Interpolant interpolant);

}  // namespace amrstream
