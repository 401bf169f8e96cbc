// Ray against the tubes' capsules. Needs the segments buffer and the params.

const uint kNoSegment = 0xffffffffu;

struct TubeHit {
  float t;
  uint segment;  // kNoSegment: no hit
};

// Distance along the unit direction d to where the ray enters the sphere, or -1 when it does
// not (a ray starting inside does not enter).
float enterSphere(vec3 o, vec3 d, vec3 centre, float r) {
  const vec3 oc = o - centre;
  const float b = dot(d, oc), h = b * b - (dot(oc, oc) - r * r);
  if (h < 0.0) return -1.0;
  const float t = -b - sqrt(h);
  return t >= 0.0 ? t : -1.0;
}

// The same for the capsule of radius r around [a, b].
float enterCapsule(vec3 o, vec3 d, vec3 a, vec3 b, float r) {
  const vec3 ab = b - a, ao = o - a;
  const float abab = dot(ab, ab), abd = dot(ab, d), abao = dot(ab, ao);
  // The infinite cylinder: |(ao + t d) x ab|^2 = r^2 |ab|^2, a quadratic A t^2 + 2 B t + C.
  const float A = abab - abd * abd;
  if (A > 1e-6 * abab) {
    const float B = abab * dot(d, ao) - abao * abd;
    const float C = abab * dot(ao, ao) - abao * abao - r * r * abab;
    const float h = B * B - A * C;
    if (h < 0.0) return -1.0;  // the capsule lies inside the cylinder
    const float t = (-B - sqrt(h)) / A;
    const float along = abao + t * abd;  // where along ab the ray enters, times |ab|^2
    if (along > 0.0 && along < abab) return t >= 0.0 ? t : -1.0;
    return enterSphere(o, d, along <= 0.0 ? a : b, r);
  }
  // Along the axis, or a segment of zero length: the nearer end sphere.
  const float ta = enterSphere(o, d, a, r), tb = enterSphere(o, d, b, r);
  if (ta < 0.0) return tb;
  return tb < 0.0 ? ta : min(ta, tb);
}

// A segment's radius: tubeRadius, or with AMRSTREAM_RENDER_RADIUS_BY_VALUE, from
// leastRadiusFraction of it at valueMin to all of it at valueMax by the mean of the segment's two
// values; outline segments are kOutlineRadiusFraction of it. The host's twin:
// render::segmentRadius.
float segmentRadius(TubeSegment s) {
  if (min(s.valueA, s.valueB) < 0.1 * AMRSTREAM_OUTLINE_VALUE)
    return kOutlineRadiusFraction * params.tubeRadius;
  if ((params.flags & AMRSTREAM_RENDER_RADIUS_BY_VALUE) == 0u) return params.tubeRadius;
  const float span = params.valueMax - params.valueMin;
  const float mean = 0.5 * s.valueA + 0.5 * s.valueB;
  const float t = span > 0.0 ? clamp((mean - params.valueMin) / span, 0.0, 1.0) : 1.0;
  return params.tubeRadius * mix(params.leastRadiusFraction, 1.0, t);
}

float enterSegment(uint id, vec3 o, vec3 d) {
  const TubeSegment s = segments[id];
  return enterCapsule(o, d, s.a, s.b, segmentRadius(s));
}
