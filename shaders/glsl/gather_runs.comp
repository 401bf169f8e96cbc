#version 460
// Copies runs of words from a source buffer into a target buffer: workgroup i copies region
// firstRegion + i (shared/gather_params.h), its invocations taking every 64th word.
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
  const GatherRegion r = regions[pc.firstRegion + gl_WorkGroupID.x];
  for (uint w = gl_LocalInvocationID.x; w < r.words; w += AMRSTREAM_GATHER_GROUP)
    target[r.target + w] = source[r.source + w];
}
