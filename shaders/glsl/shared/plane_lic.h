// A slice's LIC on the device (src/gpu/plane_lic.cpp): the grid of pixel centres that the grid
// probe samples (include/locate_probe.glsl, read at AMRSTREAM_BINDING_TRACE_PROBE_POINTS) and the
// LIC kernel's push constants and bindings (lic.comp). Scalar layout, shared with the host.
#ifndef AMRSTREAM_SHARED_PLANE_LIC_H
#define AMRSTREAM_SHARED_PLANE_LIC_H

#ifdef __cplusplus
#include "glsl_compat.h"
namespace amrstream::shared {
#endif

// Pixel (x, y)'s centre is originAnchor + originOffset + x stepX + y stepY, in finest-cell units.
struct ProbeGrid {
  ivec3 originAnchor;
  uint width;
  vec3 originOffset;
  uint height;
  vec3 stepX;
  vec3 stepY;
};

// The twin of slice::LicOptions with the plane's axes: the vector at a pixel is projected on
// axisU and axisV.
struct LicParams {
  vec3 axisU;
  uint width;
  vec3 axisV;
  uint height;
  float stepPixels;
  uint stepsEachWay;
  uint noiseSeed;
};

#define AMRSTREAM_BINDING_LIC_VECTORS 0    // vec3 per pixel, NaN where the plane has no data
#define AMRSTREAM_BINDING_LIC_INTENSITY 1  // float per pixel
#define AMRSTREAM_LIC_BINDING_COUNT 2
#define AMRSTREAM_LIC_GROUP 8  // workgroups of 8 x 8 pixels

#ifdef __cplusplus
static_assert(sizeof(ProbeGrid) == 56 && sizeof(LicParams) == 44);
}  // namespace amrstream::shared
#endif

#endif
