#version 460
// One tracing round with the host-built region tree: plain Vulkan compute, no ray tracing.
#extension GL_GOOGLE_include_directive : require
#define AMRSTREAM_LINEAR_CELL_WORDS
#include "include/amr_buffers.glsl"
#include "include/locate_tree.glsl"
#include "include/sampler.glsl"
#include "include/line_round.glsl"

layout(local_size_x_id = 0) in;  // workgroup size: specialization constant 0

void main() {
  const uint thread = gl_GlobalInvocationID.x;
  if (thread < params.lineCount) advanceLine(thread);
}
