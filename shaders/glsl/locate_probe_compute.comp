#version 460
// The probe for the `compute` backend: point location and one sample per point (include/locate_probe.glsl).
#extension GL_GOOGLE_include_directive : require
#define AMRSTREAM_PROBE_POINTS
#include "include/amr_buffers.glsl"
#include "include/locate_tree.glsl"
#include "include/sampler.glsl"
#include "include/locate_probe.glsl"

layout(local_size_x_id = 0) in;  // workgroup size: specialization constant 0

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i < params.lineCount) probeLocation(i);
}
