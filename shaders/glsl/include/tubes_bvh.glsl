// Tube intersection for the `compute` backend: a stack traversal of the host-built bounding
// volume hierarchy (src/render/tube_bvh.hpp), nearer child first.
#include "capsule.glsl"

layout(scalar, set = 0, binding = AMRSTREAM_BINDING_RENDER_TUBES)
readonly buffer TubeBvhBuffer { TubeBvhNode nodes[]; };

const uint kBvhStackSize = 64;

// Entry distance of the ray into the node's box, or a value past tMax when it misses.
float enterBox(uint node, vec3 o, vec3 inverseD, float tMax) {
  const vec3 t0 = (nodes[node].lower - o) * inverseD, t1 = (nodes[node].upper - o) * inverseD;
  const float tNear = max(max(min(t0.x, t1.x), min(t0.y, t1.y)), max(min(t0.z, t1.z), 0.0));
  const float tFar = min(min(max(t0.x, t1.x), max(t0.y, t1.y)), max(t0.z, t1.z));
  return tNear <= tFar ? tNear : tMax * 2.0 + 1.0;
}

// The nearest tube the ray enters before tMax; with `anyHit`, the first one found.
TubeHit traverseTubes(vec3 o, vec3 d, float tMax, bool anyHit) {
  TubeHit hit = TubeHit(tMax, kNoSegment);
  if (params.segmentCount == 0) return hit;
  const vec3 inverseD = 1.0 / mix(d, vec3(1e-20), lessThan(abs(d), vec3(1e-20)));
  uint stack[kBvhStackSize];
  uint depth = 0;
  uint node = 0;
  if (enterBox(0, o, inverseD, hit.t) > hit.t) return hit;
  while (true) {
    const TubeBvhNode n = nodes[node];
    if (n.count > 0) {
      for (uint i = n.first; i < n.first + n.count; ++i) {
        const float t = enterSegment(i, o, d);
        if (t >= 0.0 && t < hit.t) {
          hit = TubeHit(t, i);
          if (anyHit) return hit;
        }
      }
    } else {
      const float tl = enterBox(n.first, o, inverseD, hit.t);
      const float tr = enterBox(n.first + 1, o, inverseD, hit.t);
      const bool visitLeft = tl <= hit.t, visitRight = tr <= hit.t;
      if (visitLeft && visitRight) {
        node = tl <= tr ? n.first : n.first + 1;
        if (depth < kBvhStackSize) stack[depth++] = tl <= tr ? n.first + 1 : n.first;
        continue;
      }
      if (visitLeft || visitRight) {
        node = visitLeft ? n.first : n.first + 1;
        continue;
      }
    }
    // Pop until a node still closer than the hit.
    bool found = false;
    while (depth > 0 && !found) {
      node = stack[--depth];
      found = enterBox(node, o, inverseD, hit.t) <= hit.t;
    }
    if (!found) break;
  }
  return hit;
}

TubeHit closestTube(vec3 o, vec3 d, float tMax) { return traverseTubes(o, d, tMax, false); }
bool anyTube(vec3 o, vec3 d, float tMax) { return traverseTubes(o, d, tMax, true).segment != kNoSegment; }
