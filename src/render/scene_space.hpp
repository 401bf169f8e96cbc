#pragma once
// The space the renderer draws in: the input's cell units stretched per axis to the physical
// proportions of its finest cell, so that figures of anisotropic data (cells taller than wide)
// keep their physical shape. One scene unit is the finest cell's shortest physical side; where
// the cells are cubes, scene units are cell units.

#include <glm/glm.hpp>

#include "amrstream/cell_types.hpp"

namespace amrstream::render {

// The physical length of one scene unit: the finest cell's shortest side.
inline double sceneUnitLength(const WorldTransform& transform) {
  const glm::dvec3 side = glm::abs(transform.spacing);
  return glm::min(side.x, glm::min(side.y, side.z));
}

// Scene units per cell unit along each axis: 1 on the finest cell's shortest side, more on the
// others.
inline glm::dvec3 sceneScaleOf(const WorldTransform& transform) {
  return glm::abs(transform.spacing) / sceneUnitLength(transform);
}

// Maps scene units to physical coordinates, as `transform` maps cell units.
inline WorldTransform sceneTransformOf(const WorldTransform& transform) {
  return {transform.origin, transform.spacing / sceneScaleOf(transform)};
}

}  // namespace amrstream::render
