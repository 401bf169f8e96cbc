#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/annotations/axes.hpp"
#include "render/annotations/overlay_text.hpp"
#include "render/image/colour_scale.hpp"

namespace amrstream::render {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z"};
constexpr int kMostTicks = 5;

// Spacing, in pixels, that grows with the labels' font size s.
struct Spacing {
  float tickLength;
  float labelGap;    // mark to label, and tick labels to the axis's name
  int labelSpacing;  // the least room between two labels that both show
  float lineWidth;
};

Spacing spacingFor(int s) {
  return {.tickLength = std::max(4.0f, 0.5f * s),
          .labelGap = std::max(2.0f, 0.25f * s),
          .labelSpacing = std::max(2, s / 4),
          .lineWidth = std::max(1.0f, s / 12.0f)};
}

struct Projector {
  const OrbitCamera& camera;
  float width, height;
  std::optional<glm::vec2> operator()(glm::vec3 point) const {
    return projectToImage(camera, width, height, point);
  }
};

// Corner i of the box lies at the upper bound of axis a where bit a of i is set.
struct ProjectedBox {
  std::array<glm::vec3, 8> corners;                // cell units
  std::array<std::optional<glm::vec2>, 8> pixels;  // nullopt: behind a perspective eye
};

ProjectedBox projectBox(glm::vec3 lower, glm::vec3 upper, const Projector& project) {
  ProjectedBox box;
  for (int corner = 0; corner < 8; ++corner) {
    for (int axis = 0; axis < 3; ++axis)
      box.corners[corner][axis] = (corner >> axis & 1) ? upper[axis] : lower[axis];
    box.pixels[corner] = project(box.corners[corner]);
  }
  return box;
}

// How far (pixels) a corner may stray beyond an edge that still counts as on the outline.
constexpr float kOutlineSlack = 0.1f;

// Whether every corner lands on the inner side of the line through `point` across `outward`.
bool onOutline(const ProjectedBox& box, glm::vec2 point, glm::vec2 outward) {
  return std::ranges::all_of(box.pixels, [&](const std::optional<glm::vec2>& pixel) {
    return pixel && glm::dot(*pixel - point, outward) <= kOutlineSlack;
  });
}

struct Edge {
  int start, end;  // corners, at the lower and upper bound of the axis
  float length;    // on screen
  glm::vec2 outward;
  float distance;  // of its projected middle from the box's projected centre, across it
  bool onOutline;
};

// The edges along `axis` whose ends are both in front of the eye and land apart.
std::vector<Edge> edgesAlong(int axis, const ProjectedBox& box, glm::vec2 centre) {
  std::vector<Edge> edges;
  for (int side = 0; side < 4; ++side) {
    const int start = ((side & 1) << ((axis + 1) % 3)) | ((side >> 1) << ((axis + 2) % 3));
    const int end = start | (1 << axis);
    const std::optional<glm::vec2>& pixelStart = box.pixels[start];
    const std::optional<glm::vec2>& pixelEnd = box.pixels[end];
    if (!pixelStart || !pixelEnd) continue;
    const glm::vec2 along = *pixelEnd - *pixelStart;
    const float length = glm::length(along);
    if (!(length > 1e-3f)) continue;
    glm::vec2 outward = glm::vec2(-along.y, along.x) / length;
    float distance = glm::dot(0.5f * (*pixelStart + *pixelEnd) - centre, outward);
    if (distance < 0.0f) outward = -outward, distance = -distance;
    edges.push_back({start, end, length, outward, distance, onOutline(box, *pixelStart, outward)});
  }
  return edges;
}

// The edge along `axis` on the box's projected outline whose middle lies furthest from `centre`
// across it, if it projects at least kMinAxisEdgePixels long (else the axis is seen end-on).
// When none is on the outline (in perspective, looking into a face), the furthest of the others.
std::optional<Edge> outermostEdge(int axis, const ProjectedBox& box, glm::vec2 centre) {
  const std::vector<Edge> edges = edgesAlong(axis, box, centre);
  const bool outlineSeen = std::ranges::any_of(edges, &Edge::onOutline);
  std::optional<Edge> outermost;
  for (const Edge& edge : edges) {
    if (edge.onOutline != outlineSeen || edge.length < kMinAxisEdgePixels) continue;
    // Edges that project onto the same line (seen along a face) keep the first.
    if (!outermost || edge.distance > outermost->distance + 1e-3f) outermost = edge;
  }
  return outermost;
}

// Round values inside [lower, upper]; none for an empty range.
std::vector<ScaleTick> roundValues(double lower, double upper, int most) {
  try {
    return scaleTicks(ColourScale{ScaleKind::Linear, lower, upper}, most);
  } catch (const std::invalid_argument&) {
    return {};
  }
}

// About one tick per two and a half label heights of edge.
int mostTicksFor(float edgePixels, int labelPixelSize) {
  return std::clamp(static_cast<int>(edgePixels / (2.5f * labelPixelSize)), 2, kMostTicks);
}

// How far a box reaches along a unit direction.
float depthAlong(const PixelRect& box, glm::vec2 direction) {
  return std::abs(direction.x) * box.width + std::abs(direction.y) * box.height;
}

struct Box {
  glm::dvec3 lowerPhysical, upperPhysical;
  ProjectedBox projected;
  glm::vec2 centre;  // the projection of its centre
};

AxisLayout layoutAxis(int axis, const Box& box, const Projector& project,
                      const WorldTransform& transform, int labelPixelSize, const Spacing& space,
                      const std::string& unit) {
  AxisLayout layout;
  layout.axis = axis;
  const std::optional<Edge> edge = outermostEdge(axis, box.projected, box.centre);
  if (!edge) return layout;
  layout.shown = true;
  layout.edgeStart = box.projected.corners[edge->start];
  layout.edgeEnd = box.projected.corners[edge->end];
  layout.pixelStart = *box.projected.pixels[edge->start];
  layout.pixelEnd = *box.projected.pixels[edge->end];
  layout.outward = edge->outward;

  const float edgePixels = glm::length(layout.pixelEnd - layout.pixelStart);
  const int most = mostTicksFor(edgePixels, labelPixelSize);
  float labelDepth = 0.0f;
  for (ScaleTick& tick : roundValues(box.lowerPhysical[axis], box.upperPhysical[axis], most)) {
    glm::vec3 point = layout.edgeStart;
    point[axis] =
        static_cast<float>((tick.value - transform.origin[axis]) / transform.spacing[axis]);
    const std::optional<glm::vec2> pixel = project(point);
    if (!pixel) continue;
    AxisTick& placed = layout.ticks.emplace_back();
    placed.value = tick.value;
    placed.point = point;
    placed.pixel = *pixel;
    placed.markEnd = *pixel + space.tickLength * edge->outward;
    placed.label =
        placeTextBeyond(std::move(tick.label), placed.markEnd + space.labelGap * edge->outward,
                        edge->outward, labelPixelSize);
    labelDepth = std::max(labelDepth, depthAlong(placed.label.box, edge->outward));
  }
  const glm::vec2 middle = 0.5f * (layout.pixelStart + layout.pixelEnd);
  const float nameOffset = space.tickLength + 2.0f * space.labelGap + labelDepth;
  std::string name = kAxisNames[axis];
  if (!unit.empty()) name += " [" + unit + "]";
  layout.name = placeTextBeyond(std::move(name), middle + nameOffset * edge->outward, edge->outward,
                                labelPixelSize);
  return layout;
}

// Leaves out every label that comes within `spacing` of one kept before it, or within a label's
// height of one of another axis (two axes' values at a shared corner read as one label): the
// axes' names first, then the ticks' labels.
void leaveOutOverlappingLabels(AxesLayout& layout, int spacing) {
  struct Kept {
    PixelRect box;
    int axis;
  };
  std::vector<Kept> kept;
  const int apartAcrossAxes = std::max(spacing, layout.labelPixelSize);
  const auto keepUnlessOverlapping = [&](PlacedText& label, int axis) {
    if (label.text.empty()) return;
    for (const Kept& other : kept) {
      if (boxesOverlap(label.box, other.box, other.axis == axis ? spacing : apartAcrossAxes)) {
        label.text.clear();
        label.box.width = 0;
        return;
      }
    }
    kept.push_back({label.box, axis});
  };
  for (AxisLayout& axis : layout.axes) keepUnlessOverlapping(axis.name, axis.axis);
  for (AxisLayout& axis : layout.axes)
    for (AxisTick& tick : axis.ticks) keepUnlessOverlapping(tick.label, axis.axis);
}

}  // namespace

AxesLayout layoutAxes(const OrbitCamera& camera, std::uint32_t width, std::uint32_t height,
                      glm::dvec3 lowerPhysical, glm::dvec3 upperPhysical,
                      const WorldTransform& transform, int labelPixelSize,
                      const std::string& unit) {
  const Spacing space = spacingFor(labelPixelSize);
  AxesLayout layout;
  layout.labelPixelSize = labelPixelSize;
  layout.lineWidth = space.lineWidth;
  for (int axis = 0; axis < 3; ++axis) layout.axes[axis].axis = axis;
  if (width == 0 || height == 0) return layout;

  const Projector project{camera, static_cast<float>(width), static_cast<float>(height)};
  const glm::vec3 lowerCell(transform.toCellUnits(lowerPhysical));
  const glm::vec3 upperCell(transform.toCellUnits(upperPhysical));
  const std::optional<glm::vec2> centre = project(0.5f * (lowerCell + upperCell));
  if (!centre) return layout;
  const Box box{lowerPhysical, upperPhysical, projectBox(lowerCell, upperCell, project), *centre};
  for (int axis = 0; axis < 3; ++axis)
    layout.axes[axis] = layoutAxis(axis, box, project, transform, labelPixelSize, space, unit);
  leaveOutOverlappingLabels(layout, space.labelSpacing);
  return layout;
}

}  // namespace amrstream::render
