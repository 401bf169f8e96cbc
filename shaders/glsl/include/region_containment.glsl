// The exact half-open test that every hardware candidate must pass: AABB hits may be false
// positives, and a point on a shared face must belong to exactly one region.
bool regionContains(uint regionId, vec3 p) {
  const Region r = regions[regionId];
  return all(greaterThanEqual(p, r.lower)) && all(lessThan(p, r.upper));
}

// A zero-length ray: tMin 0 and a tiny positive tMax, because lavapipe (Mesa 25.0) reports no
// candidate for a point on a box's lower face when tMax == 0 (docs/backends.md).
const vec3 kProbeDirection = vec3(1.0);
const float kProbeTMax = 2e-10;
