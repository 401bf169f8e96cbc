// Basis-function reconstruction (docs/architecture.md, "Sampling"); twin of
// src/flow/sampler.cpp.
// Needs: the buffers of amr_buffers.glsl, params, and `int locateInRegions(ivec3 k)` (k on the
// region lattice) from the backend's locate_*.glsl, included before this file. A point is an
// anchor and an offset (cell_point.glsl).

const float kMinWeightSum = AMRSTREAM_MIN_WEIGHT_SUM;

// Specialization constant 4: the tracing kernels read the vector from dual cells
// (VolumeBuffers::dualValues) through their address, with the dual region brick records at
// AMRSTREAM_BINDING_TRACE_REGION_BRICKS; the tent interpolant only, in kernels built with
// AMRSTREAM_DUAL_ADDRESS.
layout(constant_id = 4) const bool kDualValues = false;

#ifdef AMRSTREAM_DUAL_ADDRESS
// Corner c of dual cell d: a byte offset past 2^32 carries into the address's high word.
vec4 dualCorner(uint d, int c) {
  uint carry;
  const uint low = uaddCarry(params.dualValuesAddress.x, d << 7, carry);
  return DualCellBlock(uvec2(low, params.dualValuesAddress.y + (d >> 25) + carry)).corners[c];
}
#define TENT_DUAL_VALUES kDualValues
#define TENT_DUAL_CORNER(d, c) dualCorner(d, c)
#endif

#define TENT_TYPE vec3
#define TENT_BRICK(i) regionBrickRecords[i]
#define TENT_VALUE(slot) values[slot].xyz
#define TENT_FUNCTION reconstructVector
#include "tent_reconstruction.glsl"
#undef TENT_FUNCTION
#undef TENT_VALUE

// The cell's linear model v_i + G_i (p - c_i), the dot products summed in the order of the
// CPU's glm::dot.
precise vec3 linearModel(uint slot, vec3 toP) {
#ifdef AMRSTREAM_LINEAR_CELL_WORDS
  const vec4 a = linearCellWords[3u * slot], b = linearCellWords[3u * slot + 1u],
             c = linearCellWords[3u * slot + 2u];
  const vec3 value = a.xyz, g0 = vec3(a.w, b.x, b.y), g1 = vec3(b.z, b.w, c.x),
             g2 = vec3(c.y, c.z, c.w);
#else
  const vec3 value = linearCells[4u * slot], g0 = linearCells[4u * slot + 1u],
             g1 = linearCells[4u * slot + 2u], g2 = linearCells[4u * slot + 3u];
#endif
  precise const vec3 gx = g0 * toP;
  precise const vec3 gy = g1 * toP;
  precise const vec3 gz = g2 * toP;
  return value + vec3(gx.x + gx.y + gx.z, gy.x + gy.y + gy.z, gz.x + gz.y + gz.z);
}
#define TENT_MODEL(slot, toP) linearModel(slot, toP)
#define TENT_FUNCTION reconstructVectorLinear
#include "tent_reconstruction.glsl"
#undef TENT_MODEL
#undef TENT_TYPE
#undef TENT_VALUE
#undef TENT_FUNCTION

struct VectorSample {
  bool located;
  bool valid;
  vec3 value;
  float cellWidth;
  int region;  // AMRSTREAM_NO_REGION_ID unless located
};

// The anchor moved by a whole period along the periodic axes where anchor + p left the domain;
// twin of wrapPeriodic().
ivec3 wrapPeriodic(ivec3 anchor, vec3 p) {
  if (params.periodicAxes == 0u || !isNear(p)) return anchor;
  const ivec3 cell = cellOf(anchor, p);
  for (int a = 0; a < 3; ++a) {
    if ((params.periodicAxes & (1u << a)) == 0u) continue;
    if (cell[a] >= params.domainUpper[a])
      anchor[a] -= params.period[a];
    else if (cell[a] < params.domainLower[a])
      anchor[a] += params.period[a];
  }
  return anchor;
}

// Whether lattice point k lies in the domain, [2 domainLower, 2 domainUpper) on the lattice.
bool insideDomain(ivec3 k) {
  return all(greaterThanEqual(k, 2 * params.domainLower)) && all(lessThan(k, 2 * params.domainUpper));
}

// The region of this invocation's last sample. Consecutive samples of a trace mostly fall in the
// same region, and regions are disjoint half-open boxes, so a point inside the domain and inside
// this box is in this region: the test gives the point location's answer without its tree
// descent or ray. It must come after the domain test, since a region's box may reach past the
// domain. Specialization constant 1 turns this hint off: every sample then runs the location.
layout(constant_id = 1) const bool kUseRegionHint = true;
int cachedRegionId = -1;
Region cachedRegion;

VectorSample sampleVector(ivec3 anchor, vec3 p) {
  VectorSample s = VectorSample(false, false, vec3(0.0), 0.0, AMRSTREAM_NO_REGION_ID);
  if (!isNear(p)) return s;
  const ivec3 k = latticeOf(anchor, p);
  if (!insideDomain(k)) return s;
  const bool hinted = kUseRegionHint && cachedRegionId >= 0 &&
                      all(greaterThanEqual(k, cachedRegion.lower)) &&
                      all(lessThan(k, cachedRegion.upper));
#ifdef AMRSTREAM_LOCATE_EVERY_SAMPLE  // the pipeline backend: see locate_pipeline.glsl
  const int located = locateInRegionsMasked(k, hinted ? 0x00u : 0xFFu);
  if (!hinted) {
    if (located < 0) return s;
    cachedRegionId = located;
    cachedRegion = regions[located];
  }
#else
  if (!hinted) {
    const int regionId = locateInRegions(k);
    if (regionId < 0) return s;
    cachedRegionId = regionId;
    cachedRegion = regions[regionId];
  }
#endif
  const Region region = cachedRegion;
  s.located = true;
  s.region = cachedRegionId;
  s.cellWidth = region.finestCellWidth;

  precise vec3 weighted;
  precise const float weightSum = params.linearInterpolant != 0u
                                      ? reconstructVectorLinear(region, anchor, p, weighted)
                                      : reconstructVector(region, anchor, p, weighted);
  if (!(weightSum > kMinWeightSum)) return s;
  precise const vec3 value = weighted / weightSum;
  s.value = value;
  s.valid = !any(isnan(s.value)) && !any(isinf(s.value));
  return s;
}
