#version 460
// For each point: the global id of the box that contains it (half-open [lo, hi)), or -1.
// Exercises the id scheme of src/vk/aabb_scene.hpp: instanceCustomIndex + primitiveIndex.
#extension GL_EXT_ray_query : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

layout(buffer_reference, scalar) readonly buffer Boxes { float v[]; };  // VkAabbPositionsKHR
layout(buffer_reference, scalar) readonly buffer Points { vec3 p[]; };
layout(buffer_reference, scalar) writeonly buffer Results { int id[]; };

layout(push_constant, scalar) uniform Push {
  uint64_t tlas;
  Boxes boxes;
  Points points;
  Results results;
  uint count;
} push;

bool contains(uint box, vec3 p) {
  const uint b = 6 * box;
  const vec3 lo = vec3(push.boxes.v[b], push.boxes.v[b + 1], push.boxes.v[b + 2]);
  const vec3 hi = vec3(push.boxes.v[b + 3], push.boxes.v[b + 4], push.boxes.v[b + 5]);
  return all(greaterThanEqual(p, lo)) && all(lessThan(p, hi));
}

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  const vec3 p = push.points.p[i];
  int found = -1;
  rayQueryEXT q;
  // A zero-length ray does not report candidates on a box's lower face on lavapipe: use a tiny
  // positive tMax (docs/backends.md).
  rayQueryInitializeEXT(q, accelerationStructureEXT(push.tlas), gl_RayFlagsNoneEXT, 0xFF, p, 0.0,
                        vec3(1.0), 2e-10);
  while (rayQueryProceedEXT(q)) {
    if (rayQueryGetIntersectionTypeEXT(q, false) != gl_RayQueryCandidateIntersectionAABBEXT) {
      continue;
    }
    const uint id = uint(rayQueryGetIntersectionInstanceCustomIndexEXT(q, false) +
                         rayQueryGetIntersectionPrimitiveIndexEXT(q, false));
    if (contains(id, p)) {
      found = int(id);
      rayQueryTerminateEXT(q);
    }
  }
  push.results.id[i] = found;
}
