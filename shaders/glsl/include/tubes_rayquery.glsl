// Tube intersection for the `rayquery` backend: ray queries against the segments' AABBs, each
// candidate confirmed by the exact capsule test.
#extension GL_EXT_ray_query : require
#include "capsule.glsl"

layout(set = 0, binding = AMRSTREAM_BINDING_RENDER_TUBES)
uniform accelerationStructureEXT tubeScene;

TubeHit queryTubes(vec3 o, vec3 d, float tMax, bool anyHit) {
  TubeHit hit = TubeHit(tMax, kNoSegment);
  rayQueryEXT query;
  rayQueryInitializeEXT(query, tubeScene, gl_RayFlagsNoneEXT, 0xFF, o, 0.0, d, tMax);
  while (rayQueryProceedEXT(query)) {
    if (rayQueryGetIntersectionTypeEXT(query, false) != gl_RayQueryCandidateIntersectionAABBEXT)
      continue;
    const uint id = uint(rayQueryGetIntersectionInstanceCustomIndexEXT(query, false)) +
                    uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, false));
    const float t = enterSegment(id, o, d);
    if (t >= 0.0 && t < hit.t) {
      hit = TubeHit(t, id);
      rayQueryGenerateIntersectionEXT(query, t);
      if (anyHit) rayQueryTerminateEXT(query);
    }
  }
  return hit;
}

TubeHit closestTube(vec3 o, vec3 d, float tMax) { return queryTubes(o, d, tMax, false); }
bool anyTube(vec3 o, vec3 d, float tMax) { return queryTubes(o, d, tMax, true).segment != kNoSegment; }
