// The tent basis-function sum over one region's bricks (docs/architecture.md, "Sampling"), for any value type.
// Include with TENT_TYPE (float or vec3), TENT_VALUE(slot) (the brick-ordered value at a slot)
// and TENT_FUNCTION (the name to define) defined; needs the `bricks` and `regionBricks` buffers,
// or TENT_BRICK(i) defined to give entry i of the regions' brick lists as a Brick.
// TENT_FUNCTION(region, anchor, p, weighted) returns the sum of the weights at the point
// anchor + p (cell_point.glsl) and sets `weighted` to the weighted sum of the values; the sample
// is their quotient. With TENT_MODEL(slot, toP) defined
// instead of TENT_VALUE, each value is the cell's linear model at p, toP = p - c_i (the linear
// interpolant). With TENT_DUAL_CORNER(d, c) defined (vector values only), and TENT_DUAL_VALUES
// to a true expression, values come from dual cells instead: a brick's valueOffset counts dual
// cells, each holding the values of the 2x2x2 cells from one base cell, (size + 1)^3 of them from
// base -1 (VolumeBuffers::dualValues), so that a sample's corners in one brick come from one
// 128-byte block; TENT_DUAL_CORNER(d, c) is corner c of dual cell d as a vec4.
#extension GL_EXT_control_flow_attributes : require
#ifndef TENT_DUAL_VALUES
#define TENT_DUAL_VALUES false
#endif

#ifndef TENT_BRICK
#define TENT_BRICK(i) bricks[regionBricks[i]]
#endif

float TENT_FUNCTION(Region region, ivec3 anchor, vec3 p, out TENT_TYPE weighted) {
  // `precise` forbids fusing a*b+c into an FMA, which the CPU reference never does: both paths
  // then round the same operations (NVIDIA's compiler fuses by default).
  precise float weightSum = 0.0;
  precise TENT_TYPE sum = TENT_TYPE(0.0);
  for (uint k = 0; k < region.brickCount; ++k) {
    const Brick brick = TENT_BRICK(region.brickOffset + k);
    const float width = float(1 << brick.level);
    // 2^-level, exactly: the product rounds as the CPU's quotient by the width does, and costs less.
    const float inverseWidth = uintBitsToFloat(uint(127 - brick.level) << 23);
    precise const vec3 local =
        (kDeepPositions ? vec3(anchor - brick.lower) + p : p - vec3(brick.lower)) * inverseWidth -
        0.5;
    const vec3 base = floor(local);
    precise const vec3 frac = local - base;
    const ivec3 lo = ivec3(base);
#ifdef TENT_DUAL_CORNER
    if (TENT_DUAL_VALUES) {
      // A base outside [-1, size) puts all 8 corners outside the brick: none is summed.
      if (any(lessThan(lo, ivec3(-1))) || any(greaterThanEqual(lo, brick.size))) continue;
      const uint dual = brick.valueOffset + uint((lo.x + 1) + (brick.size.x + 1) *
                                                              ((lo.y + 1) + (brick.size.y + 1) * (lo.z + 1)));
      // Unrolled, the corners' weights and loads need not wait for each other (NVIDIA's compiler
      // does not unroll the loop unasked); the sums keep their order.
      [[unroll]] for (int corner = 0; corner < 8; ++corner) {
        const vec3 offset = vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        precise const vec3 axisWeight = mix(1.0 - frac, frac, offset);
        precise const float weight = axisWeight.x * axisWeight.y * axisWeight.z;
        // A corner in the brick holds (value, 1), one outside it -0.0 throughout: adding -0.0
        // leaves any sum as it was, so without a test per corner the sums are bit for bit those
        // of the compact layout below, which skips the corners outside.
        const vec4 value = TENT_DUAL_CORNER(dual, corner);
        weightSum += weight * value.w;
        sum += weight * value.xyz;
      }
      continue;
    }
#endif
    [[unroll]] for (int corner = 0; corner < 8; ++corner) {
      const ivec3 offset = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      const ivec3 cell = lo + offset;
      if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, brick.size))) continue;
      precise const vec3 axisWeight = mix(1.0 - frac, frac, vec3(offset));
      precise const float weight = axisWeight.x * axisWeight.y * axisWeight.z;
      const uint slot = brick.valueOffset + uint(cell.x + brick.size.x * (cell.y + brick.size.y * cell.z));
      weightSum += weight;
#ifdef TENT_MODEL
      precise const vec3 toP = width * (frac - vec3(offset));
      sum += weight * TENT_MODEL(slot, toP);
#else
      sum += weight * TENT_VALUE(slot);
#endif
    }
  }
  weighted = sum;
  return weightSum;
}
#undef TENT_DUAL_VALUES
#undef TENT_DUAL_CORNER
