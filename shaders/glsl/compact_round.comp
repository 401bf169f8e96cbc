#version 460
// Compaction, pass 3: each line's points from the round's point-major slots to their dense run,
// and the state of each running line to its place for the next round.
#extension GL_GOOGLE_include_directive : require
#include "include/compaction_buffers.glsl"

layout(local_size_x = AMRSTREAM_COMPACTION_GROUP) in;

void main() {
  const uint t = gl_GlobalInvocationID.x;
  if (t >= pc.lineCount) return;
  const uvec2 first = blockSums[t / kGroup] + prefix[t];
  const LineRound r = lineRounds[t];
  for (uint k = 0; k < r.points; ++k) {
    const uint from = k * pc.lineCount + t, to = first.x + k;
    densePositions[to] = positions[from];
    denseTimes[to] = times[from];
    denseVectors[to] = vectors[from];
    denseRegionIds[to] = regionIds[from];
  }
  if (r.reason == AMRSTREAM_REASON_RUNNING) nextStates[first.y] = states[t];
}
