#version 460
// Copies runs of words from a source buffer into a target buffer (shared/gather_params.h). Per
// word, invocation i copies word firstWord + i of the dispatch's regions, found by a binary
// search of their firstWord: runs of a point or two then take one invocation a word, not a
// workgroup a run. Per run, workgroup i copies region firstRegion + i, its invocations taking
// every 64th word: a search per word costs more than it saves on long runs.
#extension GL_GOOGLE_include_directive : require
#include "shared/gather_bindings.h"
#include "shared/gather_params.h"

layout(local_size_x = AMRSTREAM_GATHER_GROUP) in;

layout(std430, set = 0, binding = AMRSTREAM_BINDING_GATHER_SOURCE)
readonly buffer Source { uint source[]; };
layout(std430, set = 0, binding = AMRSTREAM_BINDING_GATHER_TARGET)
writeonly buffer Target { uint target[]; };
layout(std430, set = 0, binding = AMRSTREAM_BINDING_GATHER_REGIONS)
readonly buffer Regions { GatherRegion regions[]; };
layout(push_constant) uniform Push { GatherParams pc; };

void main() {
  if (pc.words == 0) {
    const GatherRegion r = regions[pc.firstRegion + gl_WorkGroupID.x];
    for (uint w = gl_LocalInvocationID.x; w < r.words; w += AMRSTREAM_GATHER_GROUP)
      target[r.target + w] = source[r.source + w];
    return;
  }
  const uint word = pc.firstWord + gl_GlobalInvocationID.x;
  if (word >= pc.words) return;
  // The last region whose firstWord is at most `word`.
  uint lo = 0, hi = pc.regionCount - 1;
  while (lo < hi) {
    const uint mid = (lo + hi + 1) / 2;
    if (regions[pc.firstRegion + mid].firstWord <= word)
      lo = mid;
    else
      hi = mid - 1;
  }
  const GatherRegion r = regions[pc.firstRegion + lo];
  const uint w = word - r.firstWord;
  target[r.target + w] = source[r.source + w];
}
