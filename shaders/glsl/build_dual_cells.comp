#version 460
// Lays out the vector's dual cells (VolumeBuffers::dualValues) from the compact values on the
// device: workgroup i fills brick firstBrick + i, its invocations taking every 64th of the
// brick's (size + 1)^3 dual cells. Corner c of the dual cell from base cell b holds cell b + c as
// (value, 1) when it is in the brick and -0.0 throughout when it is not
// (include/tent_reconstruction.glsl).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_buffer_reference : require
#extension GL_EXT_buffer_reference_uvec2 : require
#include "shared/amr_types.h"
#include "shared/dual_cell_bindings.h"
#include "shared/dual_cell_params.h"

layout(local_size_x = AMRSTREAM_DUAL_CELL_GROUP) in;

layout(scalar, set = 0, binding = AMRSTREAM_BINDING_DUAL_CELL_BRICKS)
readonly buffer BrickBuffer { Brick bricks[]; };
layout(std430, set = 0, binding = AMRSTREAM_BINDING_DUAL_CELL_VALUES)
readonly buffer ValueBuffer { vec4 values[]; };
layout(std430, set = 0, binding = AMRSTREAM_BINDING_DUAL_CELL_OFFSETS)
readonly buffer DualOffsetBuffer { uint dualOffsets[]; };
layout(buffer_reference, std430, buffer_reference_align = 16) writeonly buffer DualCellBlock {
  vec4 corners[8];
};
layout(push_constant, scalar) uniform Push { DualCellParams pc; };

void main() {
  const uint b = pc.firstBrick + gl_WorkGroupID.x;
  const Brick brick = bricks[b];
  const ivec3 dims = brick.size + 1;
  const uint count = uint(dims.x * dims.y * dims.z);
  const vec4 outside = vec4(uintBitsToFloat(0x80000000u));  // -0.0, whatever constant folding does
  for (uint i = gl_LocalInvocationID.x; i < count; i += AMRSTREAM_DUAL_CELL_GROUP) {
    const ivec3 base = ivec3(i % dims.x, i / dims.x % dims.y, i / (dims.x * dims.y)) - 1;
    const uint d = dualOffsets[b] + i;
    uint carry;
    const uint low = uaddCarry(pc.dualValuesAddress.x, d << 7, carry);
    DualCellBlock block = DualCellBlock(uvec2(low, pc.dualValuesAddress.y + (d >> 25) + carry));
    for (int corner = 0; corner < 8; ++corner) {
      const ivec3 c = base + ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
      const bool inside = all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, brick.size));
      block.corners[corner] =
          inside ? vec4(values[brick.valueOffset + uint(c.x + brick.size.x * (c.y + brick.size.y * c.z))].xyz, 1.0)
                 : outside;
    }
  }
}
