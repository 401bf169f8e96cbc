#version 460
// One frame of the renderer with plain Vulkan compute: the tubes' BVH is traversed in the shader.
#extension GL_GOOGLE_include_directive : require
#include "include/render_buffers.glsl"
#include "include/locate_tree.glsl"
#include "include/tubes_bvh.glsl"
#include "include/render_frame.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  if (all(lessThan(gl_GlobalInvocationID.xy, params.imageSize))) renderPixel(gl_GlobalInvocationID.xy);
}
