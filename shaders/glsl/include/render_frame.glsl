// One frame of the tube renderer (docs/rendering.md): a jittered camera ray per pixel, the
// context volume ray-marched up to the nearest tube, the tube shaded with local lighting and
// ambient occlusion, the result added to the pixel's running mean.
// Needs render_buffers.glsl, locate_tree.glsl and one tubes_*.glsl included before it.

const float kMinWeightSum = AMRSTREAM_MIN_WEIGHT_SUM;
const uint kMaxMarchSteps = 8192;

#define TENT_TYPE float
#define TENT_VALUE(slot) scalars[slot]
#define TENT_FUNCTION reconstructScalar
#include "tent_reconstruction.glsl"
#undef TENT_FUNCTION
#define TENT_MODEL(slot, toP) (scalars[slot] + dot(scalarGradients[slot], toP))
#define TENT_FUNCTION reconstructScalarLinear
#include "tent_reconstruction.glsl"
#undef TENT_MODEL
#undef TENT_TYPE
#undef TENT_VALUE
#undef TENT_FUNCTION

uint rngState;

uint hashUint(uint v) {
  const uint state = v * 747796405u + 2891336453u;
  const uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

float random01() {
  rngState = hashUint(rngState);
  return float(rngState >> 8) * (1.0 / 16777216.0);
}

vec3 mapColour(float value) {
  const float span = params.valueMax - params.valueMin;
  const float t = span > 0.0 ? clamp((value - params.valueMin) / span, 0.0, 1.0) : 0.5;
  const float x = t * float(colourMap.length() - 1);
  const uint i = min(uint(x), uint(colourMap.length() - 2));
  return mix(colourMap[i], colourMap[i + 1], x - float(i));
}

// A unit vector around n with density proportional to cos(angle to n).
vec3 cosineDirection(vec3 n) {
  const float u = random01(), v = random01();
  const float phi = 6.2831853 * v, radius = sqrt(u);
  const vec3 helper = abs(n.x) > 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  const vec3 t = normalize(cross(helper, n)), b = cross(n, t);
  return normalize(radius * cos(phi) * t + radius * sin(phi) * b + sqrt(max(0.0, 1.0 - u)) * n);
}

vec3 shadeTube(vec3 o, vec3 d, TubeHit hit) {
  const TubeSegment s = segments[hit.segment];
  const vec3 p = o + hit.t * d;
  const vec3 ab = s.b - s.a;
  const float abab = dot(ab, ab);
  const float along = abab > 0.0 ? clamp(dot(p - s.a, ab) / abab, 0.0, 1.0) : 0.0;
  vec3 n = p - (s.a + along * ab);
  n = dot(n, n) > 0.0 ? normalize(n) : -d;
  if (dot(n, d) > 0.0) n = -n;
  const float value = mix(s.valueA, s.valueB, along);
  const vec3 base = value < 0.1 * AMRSTREAM_OUTLINE_VALUE ? params.outlineColour : mapColour(value);

  float ambient = 1.0;
  if ((params.flags & AMRSTREAM_RENDER_AO) != 0 && params.aoSamples > 0) {
    const vec3 origin = p + n * (0.02 * params.tubeRadius);
    uint open = 0;
    for (uint i = 0; i < params.aoSamples; ++i)
      if (!anyTube(origin, cosineDirection(n), params.aoDistance)) ++open;
    ambient = float(open) / float(params.aoSamples);
  }
  const float diffuse = max(dot(n, params.lightDirection), 0.0);
  const float specular = pow(max(dot(reflect(-params.lightDirection, n), -d), 0.0), 40.0);
  return base * (0.3 * ambient + 0.7 * diffuse * (0.4 + 0.6 * ambient)) + vec3(0.25 * specular * ambient);
}

vec3 backgroundColour(vec3 d) {
  if ((params.flags & AMRSTREAM_RENDER_FLAT_BACKGROUND) != 0) return params.background;
  return params.background * (0.75 + 0.25 * clamp(dot(d, params.up) * 0.5 + 0.5, 0.0, 1.0));
}

// [tEnter, tExit] of the ray in the volume's domain box; empty when tEnter > tExit.
vec2 domainSpan(vec3 o, vec3 d) {
  const vec3 inverseD = 1.0 / mix(d, vec3(1e-20), lessThan(abs(d), vec3(1e-20)));
  const vec3 t0 = (params.domainLower - o) * inverseD, t1 = (params.domainUpper - o) * inverseD;
  const float tEnter = max(max(min(t0.x, t1.x), min(t0.y, t1.y)), max(min(t0.z, t1.z), 0.0));
  const float tExit = min(min(max(t0.x, t1.x), max(t0.y, t1.y)), max(t0.z, t1.z));
  return vec2(tEnter, tExit);
}

vec3 transferColour(float x) { return mix(kVolumeLowColour, kVolumeHighColour, x); }

// Emission-absorption along the ray (in scene units) up to sceneEnd: premultiplied colour and
// opacity. The march runs in finest-cell units; the step is the finest cell width of the region
// at each sample, so fine regions are sampled finely.
vec4 marchVolume(vec3 sceneOrigin, vec3 sceneDirection, float sceneEnd) {
  const vec3 cellDirection = sceneDirection / params.sceneScale;
  const float stretch = length(cellDirection);
  const vec3 o = sceneOrigin / params.sceneScale, d = cellDirection / stretch;
  const float tEnd = sceneEnd * stretch;
  const vec2 span = domainSpan(o, d);
  vec4 result = vec4(0.0);
  float t = span.x;
  const float tStop = min(span.y, tEnd);
  if (!(t < tStop)) return result;
  float jitter = random01();
  int regionId = -1;
  Region region;
  for (uint i = 0; i < kMaxMarchSteps && t < tStop && result.a < 0.99; ++i) {
    const vec3 p = o + t * d;
    const ivec3 k = latticeOf(ivec3(0), p);  // the ray stays within the domain's box
    if (regionId < 0 || any(lessThan(k, region.lower)) || any(greaterThanEqual(k, region.upper))) {
      regionId = locateInRegions(k);
      if (regionId >= 0) region = regions[regionId];
    }
    const float step = (regionId >= 0 ? region.finestCellWidth : 1.0) * params.volumeStepScale;
    if (regionId >= 0) {
      float weighted;
      const float weightSum = (params.flags & AMRSTREAM_RENDER_LINEAR_VOLUME) != 0
                                  ? reconstructScalarLinear(region, ivec3(0), p, weighted)
                                  : reconstructScalar(region, ivec3(0), p, weighted);
      float value = weightSum > kMinWeightSum ? weighted / weightSum : 0.0;
      if ((params.flags & AMRSTREAM_RENDER_LOG_VOLUME) != 0) value = log(max(value, 1e-30)) / log(10.0);
      const float span01 = params.volumeMax - params.volumeMin;
      const float x = span01 > 0.0 ? clamp((value - params.volumeMin) / span01, 0.0, 1.0) : 0.0;
      const float sampleStep = min(step, tStop - t) * (i == 0 ? jitter : 1.0);
      const float alpha = 1.0 - exp(-params.volumeOpacity * x * x * sampleStep);
      result.rgb += (1.0 - result.a) * alpha * transferColour(x);
      result.a += (1.0 - result.a) * alpha;
    }
    t += i == 0 ? step * jitter : step;
  }
  return result;
}

void renderPixel(uvec2 pixel) {
  const uint index = pixel.y * params.imageSize.x + pixel.x;
  rngState = hashUint(index ^ hashUint(params.frameIndex * 9781u + 1u));
  const vec2 jitter = params.frameIndex == 0 ? vec2(0.5) : vec2(random01(), random01());
  const vec2 ndc = (vec2(pixel) + jitter) / vec2(params.imageSize) * 2.0 - 1.0;
  const vec3 offset = ndc.x * params.aspect * params.halfHeight * params.right -
                      ndc.y * params.halfHeight * params.up;
  const bool orthographic = (params.flags & AMRSTREAM_RENDER_ORTHOGRAPHIC) != 0;
  const vec3 d = orthographic ? params.forward : normalize(params.forward + offset);
  const vec3 o = orthographic ? params.eye + offset : params.eye;

  const TubeHit hit = closestTube(o, d, 1e30);
  const bool tube = hit.segment != kNoSegment;
  const bool transparent = (params.flags & AMRSTREAM_RENDER_TRANSPARENT) != 0;
  // Premultiplied colour and coverage; an opaque background covers every pixel.
  vec4 colour = tube ? vec4(shadeTube(o, d, hit), 1.0)
                     : (transparent ? vec4(0.0) : vec4(backgroundColour(d), 1.0));
  if ((params.flags & AMRSTREAM_RENDER_VOLUME) != 0) {
    const vec4 volume = marchVolume(o, d, tube ? hit.t : 1e30);
    colour = volume + (1.0 - volume.a) * colour;
  }

  // The running sum of the frames since the reset: frameIndex + 1 of them.
  const vec4 sum = params.frameIndex == 0 ? colour : accumulation[index] + colour;
  accumulation[index] = sum;
  const float coverage = clamp(sum.a / float(params.frameIndex + 1u), 0.0, 1.0);
  const vec3 mean = sum.a > 0.0 ? clamp(sum.rgb / sum.a, 0.0, 1.0) : vec3(0.0);
  const uvec4 bytes = uvec4(vec4(mean, transparent ? coverage : 1.0) * 255.0 + 0.5);
  pixels[index] = bytes.r | (bytes.g << 8) | (bytes.b << 16) | (bytes.a << 24);
}
