#pragma once
// A point in finest-cell units held as an integer anchor plus a float offset, so that it keeps
// float precision relative to the finest cell anywhere in a domain of up to 2^30 cells per axis
// (docs/architecture.md, "Positions"). The CPU twin of the GLSL functions of the same names in
// shaders/glsl/include/cell_point.glsl.

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace amrstream::flow {

struct CellPoint {
  glm::ivec3 anchor{0};
  glm::vec3 offset{0.0f};

  CellPoint() = default;
  CellPoint(glm::ivec3 anchorCell, glm::vec3 offsetFromIt)
      : anchor(anchorCell), offset(offsetFromIt) {}
  // A point given as float cell units, exactly: anchored at the origin.
  CellPoint(glm::vec3 cellUnits) : offset(cellUnits) {}  // NOLINT(google-explicit-constructor)
};

// Offsets at least this large (in finest cells) are outside every domain: domains span at most
// 2^30 cells per axis, centred on the origin, so an anchor inside one is within 2^29 of it.
inline constexpr float kFarOffset = 536870912.0f;  // 2^29

// The point of cell units x: whole cells in the anchor, the rest (rounded to float) in the offset.
// Anchors stay within 2^29 of the origin, where every domain lies (2^30 cells at most, centred):
// beyond, the offset holds the rest, and a point beyond 2^30 or not finite is far (not isNear).
inline CellPoint toCellPoint(glm::dvec3 x) {
  constexpr double kAnchorLimit = 536870912.0;  // 2^29
  CellPoint p;
  for (int a = 0; a < 3; ++a) {
    if (!(std::abs(x[a]) < 2.0 * kAnchorLimit)) {
      p.offset[a] = float(x[a]);
      continue;
    }
    const double whole = std::clamp(std::floor(x[a]), -kAnchorLimit, kAnchorLimit);
    p.anchor[a] = int(whole);
    p.offset[a] = float(x[a] - whole);
  }
  return p;
}

inline glm::dvec3 toCellUnits(const CellPoint& p) {
  return glm::dvec3(p.anchor) + glm::dvec3(p.offset);
}

// Whether every offset is nearer than kFarOffset (false for NaN): the condition of cellOf().
inline bool isNear(const CellPoint& p) {
  return std::abs(p.offset.x) < kFarOffset && std::abs(p.offset.y) < kFarOffset &&
         std::abs(p.offset.z) < kFarOffset;
}

// The finest cell containing the point; needs isNear(p).
inline glm::ivec3 cellOf(const CellPoint& p) { return p.anchor + glm::ivec3(glm::floor(p.offset)); }

// The point on the region lattice (doubled cell units; amr_types.h), floor(2 (anchor + offset));
// needs isNear(p) and the anchor within 2^29 of the origin (as toCellPoint and steps keep it).
inline glm::ivec3 latticeOf(const CellPoint& p) {
  return 2 * p.anchor + glm::ivec3(glm::floor(2.0f * p.offset));
}

// The same point with the offset's whole cells moved into the anchor (offset in [0, 1)); a far
// point (not isNear) unchanged. Each step's end point is sampled so, where the next step starts.
inline CellPoint normalized(const CellPoint& p) {
  if (!isNear(p)) return p;
  const glm::vec3 whole = glm::floor(p.offset);
  return {p.anchor + glm::ivec3(whole), p.offset - whole};
}

inline CellPoint moved(const CellPoint& p, glm::vec3 displacement) {
  return {p.anchor, p.offset + displacement};
}

// The lower corner of a region (lattice box lower corner `lower`) in finest cells: trace points
// leave the GPU as offsets from it.
inline glm::ivec3 regionCorner(glm::ivec3 latticeLower) {
  return glm::ivec3(latticeLower.x >> 1, latticeLower.y >> 1, latticeLower.z >> 1);
}

}  // namespace amrstream::flow
