#include "slice_plane.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "amrstream/error.hpp"

namespace amrstream::slice {

namespace {

constexpr std::uint32_t kMostPixels = 16384;

// yt's image axes of a slice across each axis: (y, z), (z, x), (x, y).
constexpr std::array<std::array<int, 2>, 3> kImageAxes{{{1, 2}, {2, 0}, {0, 1}}};

glm::dvec3 unitAxis(int axis) {
  glm::dvec3 e(0.0);
  e[axis] = 1.0;
  return e;
}

std::vector<double> numbersOf(const std::string& text) {
  std::vector<double> numbers;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string part = text.substr(start, comma - start);
    char* end = nullptr;
    const double value = std::strtod(part.c_str(), &end);
    if (part.empty() || end != part.c_str() + part.size() || !std::isfinite(value)) return {};
    numbers.push_back(value);
    start = comma + 1;
  }
  return numbers;
}

// The plane's axes for a normal that is no coordinate axis: v as near to +z as the plane allows
// (to +y where the normal is near z), u = v x n, as yt's off-axis slices take "north".
void offAxisBasis(SlicePlane& plane) {
  const glm::dvec3 n = plane.normal;
  const glm::dvec3 north = std::abs(n.z) > 0.999 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  plane.v = glm::normalize(north - glm::dot(north, n) * n);
  plane.u = glm::cross(plane.v, n);
}

void chooseNormal(SlicePlane& plane, const std::string& text) {
  for (int axis = 0; axis < 3; ++axis) {
    if (text != std::string(1, "xyz"[axis])) continue;
    plane.axis = axis;
    plane.normal = unitAxis(axis);
    plane.u = unitAxis(kImageAxes[axis][0]);
    plane.v = unitAxis(kImageAxes[axis][1]);
    return;
  }
  const std::vector<double> n = numbersOf(text);
  const glm::dvec3 normal = n.size() == 3 ? glm::dvec3(n[0], n[1], n[2]) : glm::dvec3(0.0);
  const double length = glm::length(normal);
  if (!(length > 0.0) || !std::isfinite(length))
    throw settingError("normal",
                       fmt::format("'{}' is neither x, y, z nor a non-zero NX,NY,NZ", text));
  plane.normal = normal / length;
  for (int axis = 0; axis < 3; ++axis)
    if (std::abs(plane.normal[axis]) == 1.0)
      return chooseNormal(plane, std::string(1, "xyz"[axis]));
  plane.axis = -1;
  offAxisBasis(plane);
}

// The range of the box's corners along `direction`.
glm::dvec2 extentAlong(const glm::dvec3& direction, const glm::dvec3& lower,
                       const glm::dvec3& upper) {
  glm::dvec2 range(std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity());
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                       (corner & 4) ? upper.z : lower.z);
    const double along = glm::dot(p, direction);
    range = {std::min(range.x, along), std::max(range.y, along)};
  }
  return range;
}

}  // namespace

glm::dvec3 SlicePlane::physical(glm::dvec2 planePoint) const {
  const glm::dvec2 here = planeCoordinates(point);
  return point + (planePoint.x - here.x) * u + (planePoint.y - here.y) * v;
}

glm::dvec2 SlicePlane::planeCoordinates(const glm::dvec3& physicalPoint) const {
  return {glm::dot(physicalPoint, u), glm::dot(physicalPoint, v)};
}

glm::dvec2 SlicePlane::pixelSize() const {
  return (upper - lower) / glm::dvec2(double(width), double(height));
}

glm::dvec2 SlicePlane::pixelCentre(std::uint32_t i, std::uint32_t j) const {
  return lower + (glm::dvec2(double(i), double(j)) + 0.5) * pixelSize();
}

flow::AffineGrid SlicePlane::grid() const {
  flow::AffineGrid grid;
  const glm::dvec2 size = pixelSize();
  grid.origin = physical(pixelCentre(0, 0));
  grid.steps = {size.x * u, size.y * v, glm::dvec3(0.0)};
  grid.dims = {width, height, 1};
  return grid;
}

std::array<std::string, 2> SlicePlane::axisNames() const {
  if (axis < 0) return {"a", "b"};
  return {std::string(1, "xyz"[kImageAxes[axis][0]]), std::string(1, "xyz"[kImageAxes[axis][1]])};
}

SlicePlane slicePlane(const SliceRequest& request, const glm::dvec3& domainLower,
                      const glm::dvec3& domainUpper) {
  SlicePlane plane;
  chooseNormal(plane, request.normal);
  plane.point = request.point.value_or(0.5 * (domainLower + domainUpper));
  if (!glm::all(glm::greaterThanEqual(plane.point, domainLower)) ||
      !glm::all(glm::lessThanEqual(plane.point, domainUpper)))
    throw settingError("point", fmt::format("({:g}, {:g}, {:g}) is outside the domain [{:g}, "
                                            "{:g}] x [{:g}, {:g}] x [{:g}, {:g}]",
                                            plane.point.x, plane.point.y, plane.point.z,
                                            domainLower.x, domainUpper.x, domainLower.y,
                                            domainUpper.y, domainLower.z, domainUpper.z));
  const glm::dvec2 alongU = extentAlong(plane.u, domainLower, domainUpper);
  const glm::dvec2 alongV = extentAlong(plane.v, domainLower, domainUpper);
  if (request.window) {
    const std::array<double, 4>& w = *request.window;
    plane.lower = {w[0], w[1]};
    plane.upper = {w[2], w[3]};
    if (!std::all_of(w.begin(), w.end(), [](double x) { return std::isfinite(x); }) ||
        !(w[2] > w[0]) || !(w[3] > w[1]))
      throw settingError("window", "give a0,b0,a1,b1 with a1 above a0 and b1 above b1");
    if (w[2] <= alongU.x || w[0] >= alongU.y || w[3] <= alongV.x || w[1] >= alongV.y)
      throw settingError(
          "window", fmt::format("[{:g}, {:g}] x [{:g}, {:g}] misses the domain, "
                                "which spans [{:g}, {:g}] x [{:g}, {:g}] there",
                                w[0], w[2], w[1], w[3], alongU.x, alongU.y, alongV.x, alongV.y));
  } else {
    plane.lower = {alongU.x, alongV.x};
    plane.upper = {alongU.y, alongV.y};
  }
  if (request.width < 1 || request.width > kMostPixels)
    throw settingError("width", fmt::format("{} is outside 1..{}", request.width, kMostPixels));
  plane.width = request.width;
  const glm::dvec2 extent = plane.upper - plane.lower;
  const double height = std::round(double(request.width) * extent.y / extent.x);
  if (height > double(kMostPixels))
    throw settingError("width", fmt::format("{} pixels across make the window {:.0f} high, more "
                                            "than {}",
                                            request.width, height, kMostPixels));
  plane.height = std::max<std::uint32_t>(1, std::uint32_t(height));
  return plane;
}

}  // namespace amrstream::slice
