#include "even_lines.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace amrstream::slice {

namespace {

// The neighbour grid has at most this many cells a side, so that a separation tiny beside the
// window cannot exhaust memory; its cells then grow beyond d_sep, which keeps queries right.
constexpr double kMostCellsPerSide = 2048;
constexpr int kCoarseScanPoints = 16;  // a side, for the first seed when the centre has no data
// A candidate is placed exactly d_sep from its line; rounding must not reject it.
constexpr double kSeparationSlack = 1e-9;
constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

struct Window {
  glm::dvec2 lower, upper;

  bool contains(glm::dvec2 p) const {
    return glm::all(glm::greaterThanEqual(p, lower)) && glm::all(glm::lessThanEqual(p, upper));
  }
  // The share t of the segment from p (inside) to q where it leaves the window.
  double exitShare(glm::dvec2 p, glm::dvec2 q) const {
    double t = 1.0;
    for (int a = 0; a < 2; ++a) {
      if (q[a] > upper[a]) t = std::min(t, (upper[a] - p[a]) / (q[a] - p[a]));
      if (q[a] < lower[a]) t = std::min(t, (lower[a] - p[a]) / (q[a] - p[a]));
    }
    return std::max(t, 0.0);
  }
};

// The field's unit direction at p, or nullopt where it has none (no data, zero, not finite).
// Scaled by the larger component first so that huge or tiny vectors keep their direction.
std::optional<glm::dvec2> directionAt(const PlaneVectorField& field, glm::dvec2 p) {
  const std::optional<glm::dvec2> v = field(p);
  if (!v) return std::nullopt;
  const double scale = std::max(std::abs(v->x), std::abs(v->y));
  if (!(scale > 0.0) || !std::isfinite(scale)) return std::nullopt;
  const glm::dvec2 scaled = *v / scale;
  return scaled / glm::length(scaled);
}

// The points of the lines so far, bucketed in cells at least d_sep wide: every point within d_sep
// of a query lies in the query's cell or one of the eight around it. A cell's points form a list
// through `next`, newest first, so the line traced last can be taken out again.
class NeighbourGrid {
 public:
  struct Point {
    glm::dvec2 position;
    std::size_t line;
    double arc;  // the line's arc length parameter at the point (negative on the backward part)
    std::size_t next;
  };

  NeighbourGrid(const Window& window, double separation) : lower_(window.lower) {
    for (int a = 0; a < 2; ++a) {
      const double extent = window.upper[a] - window.lower[a];
      double count = std::clamp(std::floor(extent / separation), 1.0, kMostCellsPerSide);
      while (count > 1.0 && extent / count < separation) count -= 1.0;
      counts_[a] = count;
      cellSize_[a] = extent / count;
    }
    heads_.assign(std::size_t(counts_.x * counts_.y), kNone);
  }

  void insert(glm::dvec2 p, std::size_t line, double arc) {
    std::size_t& head = heads_[cellOf(p)];
    points_.push_back({p, line, arc, head});
    head = points_.size() - 1;
  }

  void removeTrailingLine(std::size_t line) {
    while (!points_.empty() && points_.back().line == line) {
      heads_[cellOf(points_.back().position)] = points_.back().next;
      points_.pop_back();
    }
  }

  // Whether stop(point) holds for a point within `radius` (at most d_sep) of p.
  template <class Stop>
  bool anyWithin(glm::dvec2 p, double radius, Stop stop) const {
    const glm::dvec2 cell = cellCoordinates(p);
    const double radius2 = radius * radius;
    for (double y = std::max(cell.y - 1.0, 0.0); y <= std::min(cell.y + 1.0, counts_.y - 1.0);
         y += 1.0)
      for (double x = std::max(cell.x - 1.0, 0.0); x <= std::min(cell.x + 1.0, counts_.x - 1.0);
           x += 1.0)
        for (std::size_t n = heads_[std::size_t(x + counts_.x * y)]; n != kNone;
             n = points_[n].next) {
          const glm::dvec2 d = points_[n].position - p;
          if (glm::dot(d, d) < radius2 && stop(points_[n])) return true;
        }
    return false;
  }

 private:
  glm::dvec2 cellCoordinates(glm::dvec2 p) const {
    const glm::dvec2 cell = glm::floor((p - lower_) / cellSize_);
    return glm::clamp(cell, glm::dvec2(0.0), counts_ - 1.0);
  }
  std::size_t cellOf(glm::dvec2 p) const {
    const glm::dvec2 cell = cellCoordinates(p);
    return std::size_t(cell.x + counts_.x * cell.y);
  }

  glm::dvec2 lower_, cellSize_;
  glm::dvec2 counts_;  // cells a side, whole numbers
  std::vector<std::size_t> heads_;
  std::vector<Point> points_;
};

class LineTracer {
 public:
  LineTracer(const PlaneVectorField& field, const EvenLinesOptions& options, NeighbourGrid& grid)
      : field_(field),
        window_{options.lower, options.upper},
        step_(options.stepRatio * options.separation),
        testDistance_(options.testRatio * options.separation),
        selfArc_(2.0 * options.separation),
        maxPoints_(options.maxPointsPerLine),
        grid_(grid) {}

  // The line through `seed`, its points entered in the grid as line `line`; empty where the
  // field has no direction at the seed or the seed is within d_test of a line.
  std::vector<glm::dvec2> trace(glm::dvec2 seed, std::size_t line) {
    const std::optional<glm::dvec2> direction = directionAt(field_, seed);
    if (!direction || blocked(seed, line, 0.0)) return {};
    grid_.insert(seed, line, 0.0);
    std::vector<glm::dvec2> forward{seed}, backward{seed};
    extend(forward, line, 1.0, *direction, maxPoints_);
    extend(backward, line, -1.0, -*direction,
           maxPoints_ + 1 - std::min(maxPoints_, forward.size()));
    std::vector<glm::dvec2> points(backward.rbegin(), backward.rend() - 1);
    points.insert(points.end(), forward.begin(), forward.end());
    return points;
  }

 private:
  // Within d_test of another line, or of this line's own points more than 2 d_sep of arc away.
  bool blocked(glm::dvec2 p, std::size_t line, double arc) const {
    return grid_.anyWithin(p, testDistance_, [&](const NeighbourGrid::Point& other) {
      return other.line != line || std::abs(other.arc - arc) > selfArc_;
    });
  }

  // Appends RK4 steps of `sign` times the unit direction (the last point's being `direction`)
  // until a stop or until `part` has `budget` points.
  void extend(std::vector<glm::dvec2>& part, std::size_t line, double sign, glm::dvec2 direction,
              std::size_t budget) {
    const double h = step_;
    while (part.size() < budget) {
      const glm::dvec2 p = part.back();
      const double arc = sign * h * double(part.size() - 1);
      const glm::dvec2 k1 = direction;
      const std::optional<glm::dvec2> k2 = directionAt(field_, p + 0.5 * h * k1);
      if (!k2) return;
      const std::optional<glm::dvec2> k3 = directionAt(field_, p + 0.5 * h * sign * *k2);
      if (!k3) return;
      const std::optional<glm::dvec2> k4 = directionAt(field_, p + h * sign * *k3);
      if (!k4) return;
      const glm::dvec2 q = p + h / 6.0 * (k1 + 2.0 * sign * (*k2 + *k3) + sign * *k4);
      if (!window_.contains(q)) {
        const double t = window_.exitShare(p, q);
        const glm::dvec2 edge = glm::clamp(p + t * (q - p), window_.lower, window_.upper);
        if (edge != p && directionAt(field_, edge) && !blocked(edge, line, arc + sign * t * h)) {
          grid_.insert(edge, line, arc + sign * t * h);
          part.push_back(edge);
        }
        return;
      }
      const std::optional<glm::dvec2> next = directionAt(field_, q);
      if (!next || blocked(q, line, arc + sign * h)) return;
      grid_.insert(q, line, arc + sign * h);
      part.push_back(q);
      direction = sign * *next;
    }
  }

  const PlaneVectorField& field_;
  Window window_;
  double step_, testDistance_, selfArc_;
  std::size_t maxPoints_;
  NeighbourGrid& grid_;
};

double polylineLength(const std::vector<glm::dvec2>& points) {
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) length += glm::distance(points[i - 1], points[i]);
  return length;
}

bool finite(glm::dvec2 v) { return std::isfinite(v.x) && std::isfinite(v.y); }

void checkOptions(const PlaneVectorField& field, const EvenLinesOptions& options) {
  if (!field) throw std::invalid_argument("evenlySpacedLines: no field");
  if (!finite(options.lower) || !finite(options.upper) ||
      !glm::all(glm::lessThan(options.lower, options.upper)))
    throw std::invalid_argument("evenlySpacedLines: the window must be finite and not empty");
  if (!(options.separation > 0.0) || !std::isfinite(options.separation))
    throw std::invalid_argument("evenlySpacedLines: the separation must be positive and finite");
  for (const double ratio : {options.testRatio, options.stepRatio})
    if (!(ratio > 0.0 && ratio <= 1.0))
      throw std::invalid_argument("evenlySpacedLines: testRatio and stepRatio must be in (0, 1]");
}

// `count` points a side, centred in equal cells of the window, row by row from the lower edge.
glm::dvec2 scanPoint(const Window& window, glm::dvec2 count, std::size_t n) {
  const glm::dvec2 cell(double(n % std::size_t(count.x)), double(n / std::size_t(count.x)));
  return window.lower + (cell + 0.5) * (window.upper - window.lower) / count;
}

std::optional<glm::dvec2> firstSeed(const PlaneVectorField& field, const Window& window) {
  const glm::dvec2 centre = 0.5 * (window.lower + window.upper);
  if (directionAt(field, centre)) return centre;
  const glm::dvec2 count(kCoarseScanPoints);
  for (std::size_t n = 0; n < std::size_t(count.x * count.y); ++n)
    if (directionAt(field, scanPoint(window, count, n))) return scanPoint(window, count, n);
  return std::nullopt;
}

}  // namespace

std::vector<PlaneLine> evenlySpacedLines(const PlaneVectorField& field,
                                         const EvenLinesOptions& options) {
  checkOptions(field, options);
  const Window window{options.lower, options.upper};
  const double separation = options.separation;
  NeighbourGrid grid(window, separation);
  LineTracer tracer(field, options, grid);
  std::vector<PlaneLine> lines;

  const auto addLine = [&](glm::dvec2 seed) {
    std::vector<glm::dvec2> points = tracer.trace(seed, lines.size());
    if (polylineLength(points) < separation)
      grid.removeTrailingLine(lines.size());
    else
      lines.push_back({std::move(points)});
  };
  const auto isFree = [&](glm::dvec2 p) {
    return window.contains(p) && !grid.anyWithin(p, separation * (1.0 - kSeparationSlack),
                                                 [](const NeighbourGrid::Point&) { return true; });
  };

  if (const std::optional<glm::dvec2> seed = firstSeed(field, window)) addLine(*seed);

  const glm::dvec2 scanCount =
      glm::max(glm::ceil((window.upper - window.lower) / separation), glm::dvec2(1.0));
  const double scanPoints = scanCount.x * scanCount.y;
  double scanned = 0.0;
  std::size_t seeding = 0;  // the first line whose candidates are still to be tried
  while (true) {
    for (; seeding < lines.size(); ++seeding) {
      // `lines` grows as candidates succeed, so the line is read by index, not by reference.
      for (std::size_t i = 0; i < lines[seeding].points.size(); ++i) {
        const std::vector<glm::dvec2>& points = lines[seeding].points;
        const glm::dvec2 p = points[i];
        const glm::dvec2 tangent =
            points[std::min(i + 1, points.size() - 1)] - points[i ? i - 1 : 0];
        if (tangent == glm::dvec2(0.0)) continue;
        const glm::dvec2 normal = glm::normalize(glm::dvec2(-tangent.y, tangent.x));
        for (const double side : {1.0, -1.0}) {
          const glm::dvec2 candidate = p + side * separation * normal;
          if (isFree(candidate)) addLine(candidate);
        }
      }
    }
    const std::size_t before = lines.size();
    for (; scanned < scanPoints && lines.size() == before; scanned += 1.0) {
      const glm::dvec2 p = scanPoint(window, scanCount, std::size_t(scanned));
      if (isFree(p)) addLine(p);
    }
    if (lines.size() == before) return lines;
  }
}

}  // namespace amrstream::slice
