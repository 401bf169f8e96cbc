// One tracing round with the host-built region tree: plain Vulkan compute, no ray tracing. The
// entry points trace_compute.comp and trace_compute_compact.comp differ in whether they can read
// dual cells, which take a buffer device address (AMRSTREAM_DUAL_ADDRESS).
#define AMRSTREAM_LINEAR_CELL_WORDS
#include "amr_buffers.glsl"
#include "locate_tree.glsl"
#include "sampler.glsl"
#include "line_round.glsl"

layout(local_size_x_id = 0) in;  // workgroup size: specialization constant 0

void main() {
  advanceLineOfInvocation(gl_GlobalInvocationID.x);
}
