#version 460
// Streamline tracing with zero-length ray queries against the regions' AABBs.
#extension GL_GOOGLE_include_directive : require
#define AMRSTREAM_DUAL_ADDRESS  // acceleration structures need buffer device addresses anyway
#include "include/amr_buffers.glsl"
#include "include/locate_rayquery.glsl"
#include "include/sampler.glsl"
#include "include/line_round.glsl"

layout(local_size_x_id = 0) in;  // workgroup size: specialization constant 0

void main() {
  advanceLineOfInvocation(gl_GlobalInvocationID.x);
}
