// Point location for the `rayquery` backend: a zero-length ray query against the regions' AABBs.
#extension GL_EXT_ray_query : require
#include "region_containment.glsl"

layout(set = 0, binding = AMRSTREAM_BINDING_TRACE_LOCATE)
uniform accelerationStructureEXT regionScene;

int locateInRegions(ivec3 k) {
  rayQueryEXT query;
  rayQueryInitializeEXT(query, regionScene, gl_RayFlagsNoneEXT, 0xFF, probeOrigin(k), 0.0,
                        kProbeDirection,
                        kProbeTMax);
  int found = -1;
  while (rayQueryProceedEXT(query)) {
    if (rayQueryGetIntersectionTypeEXT(query, false) != gl_RayQueryCandidateIntersectionAABBEXT)
      continue;
    const uint id = uint(rayQueryGetIntersectionInstanceCustomIndexEXT(query, false)) +
                    uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, false));
    if (regionContains(id, k)) {
      found = int(id);
      rayQueryTerminateEXT(query);
    }
  }
  return found;
}
