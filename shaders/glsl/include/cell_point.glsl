// A point in finest-cell units as an integer anchor plus a float offset (docs/architecture.md,
// "Positions"); twin of src/flow/cell_point.hpp.
#ifndef AMRSTREAM_CELL_POINT_GLSL
#define AMRSTREAM_CELL_POINT_GLSL

// Specialization constant 3: deep positions (TraceParams::deepPositions). Off (the kernels that
// do not set it: render, probes), every anchor is zero and offsets are float cell units, so the
// tent takes p - brick.lower in float, as the CPU then does; on, the anchors follow the lines and
// the tent takes the exact integer difference first.
layout(constant_id = 3) const bool kDeepPositions = false;

// Offsets at least this large are outside every domain (at most 2^30 cells, centred).
const float kFarOffset = 536870912.0;

bool isNear(vec3 offset) {
  return max(max(abs(offset.x), abs(offset.y)), abs(offset.z)) < kFarOffset;
}

// The finest cell containing the point; needs isNear(offset).
ivec3 cellOf(ivec3 anchor, vec3 offset) { return anchor + ivec3(floor(offset)); }

// The point on the region lattice (doubled cell units), floor(2 (anchor + offset)); needs
// isNear(offset) and |anchor| <= 2^29 (anchors are clamped so: cell_point.hpp).
ivec3 latticeOf(ivec3 anchor, vec3 offset) { return 2 * anchor + ivec3(floor(2.0 * offset)); }

// The lower corner, in finest cells, of the region whose lattice box starts at latticeLower.
ivec3 regionCorner(ivec3 latticeLower) { return latticeLower >> 1; }

#endif
