#version 460
// The grid probe for the `compute` backend: the vector at a slice's pixel centres (include/locate_probe.glsl).
#extension GL_GOOGLE_include_directive : require
#define AMRSTREAM_PROBE_GRID
#include "include/amr_buffers.glsl"
#include "include/locate_tree.glsl"
#include "include/sampler.glsl"
#include "include/locate_probe.glsl"

layout(local_size_x_id = 0) in;  // workgroup size: specialization constant 0; one row per y

void main() {
  const uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x < probeGrid.width && pixel.y < probeGrid.height) probeGridPoint(pixel);
}
