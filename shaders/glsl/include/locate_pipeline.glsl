// Point location for the `pipeline` backend: traceRayEXT from the ray generation shader; the
// intersection shader (locate.rint) does the containment test and the closest-hit shader
// (locate.rchit) returns the region id in the payload; the miss shader returns -1.
#extension GL_EXT_ray_tracing : require
#include "region_containment.glsl"

layout(set = 0, binding = 11) uniform accelerationStructureEXT regionScene;
layout(location = 0) rayPayloadEXT int locatedRegion;

int locateInRegions(vec3 p) {
  locatedRegion = -1;
  traceRayEXT(regionScene, gl_RayFlagsTerminateOnFirstHitEXT, 0xFF, 0, 0, 0, p, 0.0,
              kProbeDirection, kProbeTMax, 0);
  return locatedRegion;
}
