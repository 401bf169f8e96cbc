#version 460
// The point data of a round's compacted points: the point-data channels reconstructed with the
// tent method at each point, in the region its vector sample found, and the curl of the
// reconstructed vector; twin of sampleChannels() and sampleVorticity() in src/flow/sampler.cpp.
// Dispatched indirectly with the round's point count (RoundSummary).
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require

#include "shared/amr_types.h"
#include "shared/round_bindings.h"
#include "shared/round_params.h"
#include "include/cell_point.glsl"

layout(push_constant, scalar) uniform PointDataBlock { PointDataParams pc; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_BRICKS)
readonly buffer BrickBuffer { Brick bricks[]; };
layout(std430, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_VALUES)
readonly buffer ValueBuffer { vec4 values[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_REGIONS)
readonly buffer RegionBuffer { Region regions[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_REGION_BRICKS)
readonly buffer RegionBrickBuffer { Brick regionBricks[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_CHANNEL_VALUES)
readonly buffer ChannelValueBuffer { float channelValues[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_SUMMARY)
readonly buffer SummaryBuffer { RoundSummary summary; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_POSITIONS)
readonly buffer PositionBuffer { vec3 positions[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_REGION_IDS)
readonly buffer RegionIdBuffer { int regionIds[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_CHANNELS)
writeonly buffer ChannelBuffer { float channels[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_VORTICITY)
writeonly buffer VorticityBuffer { vec3 vorticity[]; };
// The linear interpolant's cells (per slot the value, then the gradients of its three
// components) and channel gradients (per slot and channel), per finest cell; one element each,
// unread, with the tent interpolant.
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_LINEAR_CELLS)
readonly buffer LinearCellBuffer { vec3 linearCells[]; };
layout(scalar, set = 0, binding = AMRSTREAM_BINDING_POINT_DATA_CHANNEL_GRADIENTS)
readonly buffer ChannelGradientBuffer { vec3 channelGradients[]; };

layout(local_size_x = AMRSTREAM_POINT_DATA_GROUP) in;

const float kMinWeightSum = AMRSTREAM_MIN_WEIGHT_SUM;
#define kNaN uintBitsToFloat(0x7fc00000u)

// The 2x2x2 cells of one brick around the point anchor + p, in the order every reconstruction
// sums them: the brick's local coordinates once, then tentCell() per corner.
struct TentBrick {
  Brick brick;
  float width;
  vec3 frac;
  ivec3 lo;
};

TentBrick tentBrick(Brick brick, ivec3 anchor, vec3 p) {
  TentBrick t;
  t.brick = brick;
  t.width = float(1 << t.brick.level);
  precise const vec3 local = (vec3(anchor - t.brick.lower) + p) / t.width - 0.5;
  const vec3 base = floor(local);
  precise const vec3 frac = local - base;
  t.frac = frac;
  t.lo = ivec3(base);
  return t;
}

// False when the corner's cell lies outside the brick.
bool tentCell(TentBrick t, int corner, out uint slot, out vec3 axisWeight, out vec3 offset) {
  const ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
  const ivec3 cell = t.lo + o;
  slot = 0u;
  axisWeight = vec3(0.0);
  offset = vec3(o);
  if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, t.brick.size))) return false;
  precise const vec3 w = mix(1.0 - t.frac, t.frac, vec3(o));
  axisWeight = w;
  slot = t.brick.valueOffset + uint(cell.x + t.brick.size.x * (cell.y + t.brick.size.y * cell.z));
  return true;
}

// The anchor of a point in `region` (line_state.h): its corner, or the origin.
ivec3 anchorOf(Region region) {
  return pc.deepPositions != 0u ? regionCorner(region.lower) : ivec3(0);
}

void sampleChannels(uint point, int regionId, vec3 p) {
  const uint count = pc.channelCount;
  for (uint first = 0; first < count; first += 4) {
    precise float weightSum = 0.0;
    precise vec4 sum = vec4(0.0);
    if (regionId >= 0) {
      const Region region = regions[regionId];
      for (uint k = 0; k < region.brickCount; ++k) {
        const TentBrick t = tentBrick(regionBricks[region.brickOffset + k], anchorOf(region), p);
        for (int corner = 0; corner < 8; ++corner) {
          uint slot;
          vec3 a, offset;
          if (!tentCell(t, corner, slot, a, offset)) continue;
          precise const float weight = a.x * a.y * a.z;
          weightSum += weight;
          for (uint j = 0; j < 4 && first + j < count; ++j)
            sum[j] += weight * channelValues[slot * count + first + j];
          if (pc.linearInterpolant == 0u) continue;
          precise const vec3 toP = t.width * (t.frac - offset);
          for (uint j = 0; j < 4 && first + j < count; ++j) {
            precise const vec3 g = channelGradients[slot * count + first + j] * toP;
            sum[j] += weight * (g.x + g.y + g.z);
          }
        }
      }
    }
    for (uint j = 0; j < 4 && first + j < count; ++j) {
      precise const float value = sum[j] / weightSum;
      channels[point * count + first + j] = weightSum > kMinWeightSum ? value : kNaN;
    }
  }
}

vec3 sampleVorticity(int regionId, vec3 p) {
  if (regionId < 0) return vec3(kNaN);
  precise float weightSum = 0.0;
  precise vec3 weighted = vec3(0.0), weightGradient = vec3(0.0);
  precise vec3 weightedGradient[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
  precise vec3 weightedModelGradient[3] = vec3[3](vec3(0.0), vec3(0.0), vec3(0.0));
  const Region region = regions[regionId];
  for (uint k = 0; k < region.brickCount; ++k) {
    const TentBrick t = tentBrick(regionBricks[region.brickOffset + k], anchorOf(region), p);
    for (int corner = 0; corner < 8; ++corner) {
      uint slot;
      vec3 a, offset;
      if (!tentCell(t, corner, slot, a, offset)) continue;
      precise const vec3 da = (2.0 * offset - 1.0) / t.width;
      precise const float weight = a.x * a.y * a.z;
      precise const vec3 gradient = vec3(da.x * a.y * a.z, a.x * da.y * a.z, a.x * a.y * da.z);
      precise vec3 v = values[slot].xyz;
      if (pc.linearInterpolant != 0u) {  // the cell's model v_i + G_i (p - c_i), its derivative G_i
        precise const vec3 toP = t.width * (t.frac - offset);
        const vec3 g0 = linearCells[4u * slot + 1u], g1 = linearCells[4u * slot + 2u],
                   g2 = linearCells[4u * slot + 3u];
        precise const vec3 m0 = g0 * toP, m1 = g1 * toP, m2 = g2 * toP;
        v += vec3(m0.x + m0.y + m0.z, m1.x + m1.y + m1.z, m2.x + m2.y + m2.z);
        for (int d = 0; d < 3; ++d) weightedModelGradient[d] += weight * vec3(g0[d], g1[d], g2[d]);
      }
      weightSum += weight;
      weighted += weight * v;
      weightGradient += gradient;
      for (int d = 0; d < 3; ++d) weightedGradient[d] += gradient[d] * v;
    }
  }
  if (!(weightSum > kMinWeightSum)) return vec3(kNaN);
  precise const vec3 value = weighted / weightSum;
  precise vec3 jacobian[3];
  for (int d = 0; d < 3; ++d)
    jacobian[d] = (weightedGradient[d] - value * weightGradient[d] + weightedModelGradient[d]) /
                  weightSum * pc.cellsPerPhysical[d];
  precise const vec3 curl = vec3(jacobian[1].z - jacobian[2].y, jacobian[2].x - jacobian[0].z,
                                 jacobian[0].y - jacobian[1].x);
  return curl;
}

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i >= summary.points) return;
  const vec3 p = positions[i];
  const int regionId = regionIds[i];
  sampleChannels(i, regionId, p);
  if (pc.computeVorticity != 0u) vorticity[i] = sampleVorticity(regionId, p);
}
