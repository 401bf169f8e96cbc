// Basis-function reconstruction (DESIGN.md section 5); twin of src/flow/sampler.cpp.
// Needs: the buffers of amr_buffers.glsl, params, and `int locateInRegions(vec3 p)` from the
// backend's locate_*.glsl, included before this file.

const float kMinWeightSum = 1e-20;

struct VectorSample {
  bool located;
  bool valid;
  vec3 value;
  float cellWidth;
};

int locateRegion(vec3 p) {
  if (any(lessThan(p, vec3(params.domainLower))) ||
      any(greaterThanEqual(p, vec3(params.domainUpper))))
    return -1;
  return locateInRegions(p);
}

VectorSample sampleVector(vec3 p) {
  VectorSample s = VectorSample(false, false, vec3(0.0), 0.0);
  const int regionId = locateRegion(p);
  if (regionId < 0) return s;
  const Region region = regions[regionId];
  s.located = true;
  s.cellWidth = region.finestCellWidth;

  // `precise` forbids fusing a*b+c into an FMA, which the CPU reference never does: both paths
  // then round the same operations (NVIDIA's compiler fuses by default).
  precise float weightSum = 0.0;
  precise vec3 weighted = vec3(0.0);
  for (uint k = 0; k < region.brickCount; ++k) {
    const Brick brick = bricks[regionBricks[region.brickOffset + k]];
    const float width = float(1 << brick.level);
    precise const vec3 local = (p - vec3(brick.lower)) / width - 0.5;
    const vec3 base = floor(local);
    precise const vec3 frac = local - base;
    const ivec3 lo = ivec3(base);
    for (int corner = 0; corner < 8; ++corner) {
      const ivec3 offset = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      const ivec3 cell = lo + offset;
      if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, brick.size))) continue;
      precise const vec3 axisWeight = mix(1.0 - frac, frac, vec3(offset));
      precise const float weight = axisWeight.x * axisWeight.y * axisWeight.z;
      const uint slot = brick.valueOffset + uint(cell.x + brick.size.x * (cell.y + brick.size.y * cell.z));
      weightSum += weight;
      weighted += weight * values[slot];
    }
  }
  if (!(weightSum > kMinWeightSum)) return s;
  precise const vec3 value = weighted / weightSum;
  s.value = value;
  s.valid = !any(isnan(s.value)) && !any(isinf(s.value));
  return s;
}
