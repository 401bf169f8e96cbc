// Point location for the `pipeline` backend: traceRayEXT from the ray generation shader; the
// intersection shader (locate.rint) does the containment test and the closest-hit shader
// (locate.rchit) returns the region id in the payload; the miss shader returns -1.
#extension GL_EXT_ray_tracing : require
#include "region_containment.glsl"

layout(set = 0, binding = AMRSTREAM_BINDING_TRACE_LOCATE)
uniform accelerationStructureEXT regionScene;
layout(location = 0) rayPayloadEXT int locatedRegion;

// With the region hint (sampler.glsl), the ray is traced at every sample, with an empty cull
// mask when the hint already gives the region: NVIDIA's driver 580 returns wrong traces with
// traceRayEXT behind the hint's branch and right ones with the call in uniform control flow
// (docs/performance-notes.md, "The pipeline's ray behind the hint's branch"). An empty mask
// meets no geometry, so such a ray costs a launch and a miss.
#define AMRSTREAM_LOCATE_EVERY_SAMPLE

// The intersection shader recovers k from the ray's origin (latticeOfProbe), which is exact
// while |k| < 2^23: the backend refuses domains wider than 2^22 finest cells.
int locateInRegionsMasked(ivec3 k, uint cullMask) {
  locatedRegion = -1;
  traceRayEXT(regionScene, gl_RayFlagsTerminateOnFirstHitEXT, cullMask, 0, 0, 0, probeOrigin(k),
              0.0, kProbeDirection, kProbeTMax, 0);
  return locatedRegion;
}

int locateInRegions(ivec3 k) { return locateInRegionsMasked(k, 0xFFu); }
