// Tube intersection for the `pipeline` backend: traceRayEXT from the ray generation shader; the
// intersection shader (tube.rint) runs the capsule test, the closest-hit shader (tube.rchit)
// returns the segment, the miss shader (tube.rmiss) reports none.
#extension GL_EXT_ray_tracing : require
#include "capsule.glsl"

layout(set = 0, binding = AMRSTREAM_BINDING_RENDER_TUBES)
uniform accelerationStructureEXT tubeScene;
layout(location = 0) rayPayloadEXT TubeHit tubePayload;

TubeHit closestTube(vec3 o, vec3 d, float tMax) {
  tubePayload = TubeHit(tMax, kNoSegment);
  traceRayEXT(tubeScene, gl_RayFlagsNoneEXT, 0xFF, 0, 0, 0, o, 0.0, d, tMax, 0);
  return tubePayload;
}

bool anyTube(vec3 o, vec3 d, float tMax) {
  tubePayload = TubeHit(tMax, 0u);
  traceRayEXT(tubeScene, gl_RayFlagsTerminateOnFirstHitEXT | gl_RayFlagsSkipClosestHitShaderEXT,
              0xFF, 0, 0, 0, o, 0.0, d, tMax, 0);
  return tubePayload.segment != kNoSegment;
}
