// Point location for the `pipeline` backend: traceRayEXT from the ray generation shader; the
// intersection shader (locate.rint) does the containment test and the closest-hit shader
// (locate.rchit) returns the region id in the payload; the miss shader returns -1.
#extension GL_EXT_ray_tracing : require
#include "region_containment.glsl"

layout(set = 0, binding = AMRSTREAM_LOCATE_BINDING) uniform accelerationStructureEXT regionScene;
layout(location = 0) rayPayloadEXT int locatedRegion;

// With the region hint (sampler.glsl), the ray is traced at every sample, with an empty cull
// mask when the hint already gives the region: NVIDIA's driver 580 returned wrong traces when
// traceRayEXT sat behind the hint's branch (traces ended early on an H200, where lavapipe and the
// CPU agreed), and is right with the call in uniform control flow. An empty mask meets no
// geometry, so such a ray costs a launch and a miss.
#define AMRSTREAM_LOCATE_EVERY_SAMPLE

int locateInRegionsMasked(vec3 p, uint cullMask) {
  locatedRegion = -1;
  traceRayEXT(regionScene, gl_RayFlagsTerminateOnFirstHitEXT, cullMask, 0, 0, 0, p, 0.0,
              kProbeDirection, kProbeTMax, 0);
  return locatedRegion;
}

int locateInRegions(vec3 p) { return locateInRegionsMasked(p, 0xFFu); }
