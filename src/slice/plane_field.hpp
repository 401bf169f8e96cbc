#pragma once
// The vector's part in a slice's plane: exactly at any point (what the field lines follow), and
// at the pixel centres sampled once (what the LIC convolves).

#include "even_lines.hpp"
#include "flow/uniform_resample.hpp"
#include "flow/vector_volume.hpp"
#include "lic.hpp"
#include "slice_plane.hpp"

namespace amrstream::slice {

// The reconstruction at the plane point, projected on the plane's axes; nullopt where it is not
// valid. For one thread at a time (it keeps the last region found); `volume` and `plane` must
// outlive it.
PlaneVectorField exactInPlane(const flow::VectorVolume& volume, const SlicePlane& plane);

// The samples of plane.grid() projected on the plane's axes.
VectorImage inPlaneImage(const SlicePlane& plane, const flow::GridSamples& samples);

}  // namespace amrstream::slice
