#version 460
// Compaction, pass 1: within each workgroup, the exclusive prefix sum of the lines' (points,
// running) and the workgroup's total.
#extension GL_GOOGLE_include_directive : require
#include "include/compaction_buffers.glsl"

layout(local_size_x = AMRSTREAM_COMPACTION_GROUP) in;

void main() {
  const uint t = gl_GlobalInvocationID.x, l = gl_LocalInvocationID.x;
  uvec2 own = uvec2(0);
  if (t < pc.lineCount) {
    const LineRound r = lineRounds[t];
    own = uvec2(r.points, r.reason == AMRSTREAM_REASON_RUNNING ? 1u : 0u);
  }
  partial[l] = own;
  scanPartials();
  if (t < pc.lineCount) prefix[t] = partial[l] - own;
  if (l == kGroup - 1) blockSums[gl_WorkGroupID.x] = partial[l];
}
