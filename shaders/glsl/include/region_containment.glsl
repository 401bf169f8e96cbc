// The exact half-open test on the region lattice that every hardware candidate must pass: the
// acceleration structure's float boxes are rounded outward, so its hits may be false positives.
bool regionContains(uint regionId, ivec3 k) {
  const Region r = regions[regionId];
  return all(greaterThanEqual(k, r.lower)) && all(lessThan(k, r.upper));
}

// The acceleration structure holds the region boxes in half lattice units (finest cells), and a
// lattice point k is probed at the centre of its lattice cell: exact in float while |k| < 2^23,
// where the boxes are exact too and the centre is never on a face (src/gpu/volume_buffers.cpp).
vec3 probeOrigin(ivec3 k) { return (vec3(k) + 0.5) * 0.5; }
ivec3 latticeOfProbe(vec3 origin) { return ivec3(floor(2.0 * origin)); }

// A zero-length ray: tMin 0 and a tiny positive tMax, because lavapipe (Mesa 25.0) reports no
// candidate for a point on a box's lower face when tMax == 0 (docs/backends.md).
const vec3 kProbeDirection = vec3(1.0);
const float kProbeTMax = 2e-10;
