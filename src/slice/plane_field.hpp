#pragma once
// The vector's part in a slice's plane: exactly at any point (what the field lines follow), and
// at the pixel centres sampled once (what the background shows and the LIC convolves).

#include <functional>

#include "../../shaders/glsl/shared/plane_lic.h"
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

// The plane's pixel centres in `volume`'s finest-cell units: the first centre anchored at its
// cell, the steps between centres in float.
shared::ProbeGrid pixelGrid(const flow::VectorVolume& volume, const SlicePlane& plane);

// The vector and the point data at every point of `grid` (x fastest), each point computed in
// float from the anchored origin as the device's grid probe computes it
// (shaders/glsl/include/locate_probe.glsl), so that both sample the same points. On all cores;
// `progress(done)` is called from one thread at a time with the rows done.
flow::GridSamples samplePixels(const flow::VectorVolume& volume, const shared::ProbeGrid& grid,
                               const std::function<void(std::size_t)>& progress = {});

// The LIC kernel's parameters (shaders/glsl/lic.comp) for the plane's pixels and `options`.
shared::LicParams licParams(const SlicePlane& plane, const LicOptions& options);

// The samples of the plane's pixels projected on the plane's axes.
VectorImage inPlaneImage(const SlicePlane& plane, const flow::GridSamples& samples);

}  // namespace amrstream::slice
