#version 460
// Compaction, pass 2 (one workgroup): the exclusive prefix sum of the workgroup totals, in place,
// and the round's totals for the host and for the point data kernel's indirect dispatch.
#extension GL_GOOGLE_include_directive : require
#include "include/compaction_buffers.glsl"

layout(local_size_x = AMRSTREAM_COMPACTION_GROUP) in;

void main() {
  const uint l = gl_LocalInvocationID.x;
  const uint blocks = (pc.lineCount + kGroup - 1) / kGroup;
  uvec2 carry = uvec2(0);
  for (uint first = 0; first < blocks; first += kGroup) {
    const uint i = first + l;
    const uvec2 own = i < blocks ? blockSums[i] : uvec2(0);
    partial[l] = own;
    scanPartials();
    if (i < blocks) blockSums[i] = carry + partial[l] - own;
    carry += partial[kGroup - 1];
    barrier();  // every invocation has read the total before the next chunk overwrites it
  }
  if (l == 0) {
    summary.points = carry.x;
    summary.liveLines = carry.y;
    summary.pointGroups = uvec3((carry.x + AMRSTREAM_POINT_DATA_GROUP - 1) / AMRSTREAM_POINT_DATA_GROUP, 1, 1);
  }
}
