#pragma once
// A slice's plane and its pixels. Plane coordinates (a, b) of a point p are p.u and p.v: along
// the axes themselves for a plane across x, y or z (yt's image axes: (y, z) across x, (z, x)
// across y, (x, y) across z), so the figure's axes read physical coordinates.

#include <array>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>

#include "flow/uniform_resample.hpp"

namespace amrstream::slice {

struct SliceRequest {
  std::string normal = "z";         // x, y, z, or NX,NY,NZ
  std::optional<glm::dvec3> point;  // the plane passes through it; default: the domain's centre
  std::optional<std::array<double, 4>> window;  // a0,b0,a1,b1; default: the domain, seen across
  std::uint32_t width = 1024;                   // pixels along a; along b in proportion
};

struct SlicePlane {
  glm::dvec3 normal{0, 0, 1}, u{1, 0, 0}, v{0, 1, 0};  // unit; u x v = normal
  glm::dvec3 point{0.0};                               // on the plane
  glm::dvec2 lower{0.0}, upper{1.0};                   // the window, in plane coordinates
  std::uint32_t width = 1, height = 1;                 // pixels
  int axis = 2;  // 0, 1, 2 for a plane across x, y, z; -1 for any other normal

  glm::dvec3 physical(glm::dvec2 planePoint) const;
  glm::dvec2 planeCoordinates(const glm::dvec3& physicalPoint) const;
  glm::dvec2 pixelSize() const;
  // The centre of pixel (i, j), j counted from the window's lower edge.
  glm::dvec2 pixelCentre(std::uint32_t i, std::uint32_t j) const;
  // The pixel centres as a grid for flow::sampleGrid (x fastest, row 0 at the lower edge).
  flow::AffineGrid grid() const;
  // "x", "y", "z" for the plane's axes across an axis; "a", "b" otherwise.
  std::array<std::string, 2> axisNames() const;
};

// The plane the request asks for in the domain [lower, upper]. Throws InputError naming
// --normal, --point, --window or --width for a normal that is not an axis or a finite non-zero
// vector, a point outside the domain, an empty window or one that misses the domain, or a width
// outside 1..16384 (or whose height would be).
SlicePlane slicePlane(const SliceRequest& request, const glm::dvec3& domainLower,
                      const glm::dvec3& domainUpper);

}  // namespace amrstream::slice
