#pragma once
// Evenly spaced field lines in a plane, after Jobard and Lefer, "Creating evenly-spaced
// streamlines of arbitrary density" (1997), as VTK's vtkEvenlySpacedStreamlines2D draws them:
// the lines of a slice figure, following the in-plane part of a vector field.

#include <cstddef>
#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace amrstream::slice {

// The in-plane vector at a point of the plane (plane coordinates), or nullopt where there is no
// data.
using PlaneVectorField = std::function<std::optional<glm::dvec2>(glm::dvec2)>;

struct EvenLinesOptions {
  glm::dvec2 lower{0.0}, upper{1.0};  // the window the lines stay in
  double separation = 0.05;           // d_sep: the distance between neighbouring lines
  double testRatio = 0.5;  // a line stops where it comes within testRatio * separation of another
  double stepRatio = 0.1;  // the step, as a share of the separation
  std::size_t maxPointsPerLine = 20000;
};

struct PlaneLine {
  std::vector<glm::dvec2> points;  // in the field's direction
};

// Lines of the field's direction (RK4 on the unit vector, step stepRatio * separation), each
// traced both ways from its seed and joined (backward part reversed, then forward), stopping at
// the window's edge (the last step cut there), where the field has no data or vanishes (or is not
// finite), within d_test of another line, where it closes on itself (comes within d_test of its
// own points more than 2 * separation of arc length back: a closed loop ends there, not before),
// or at maxPointsPerLine.
// Seeds: the first at the window's centre (or, where the field has none there, the first point
// of a coarse scan with data); then, as Jobard and Lefer do, candidates at distance d_sep on both
// sides of every accepted line's points (perpendicular to it), taken in order while they are at
// least d_sep from every line; when those run out, a scan of the window on a grid of spacing
// d_sep fills what is left. Lines shorter than one separation are dropped. Neighbour queries use
// a uniform grid of cells of size d_sep (no quadratic search). Deterministic. Throws
// std::invalid_argument for an empty field, a window that is empty or not finite, a separation
// that is not positive and finite, or ratios outside (0, 1].
std::vector<PlaneLine> evenlySpacedLines(const PlaneVectorField& field,
                                         const EvenLinesOptions& options);

}  // namespace amrstream::slice
