#pragma once
// The result of tracing: polylines ("lines"), each one seed traced in one direction, stored one
// after the other (compressed rows: the points of line i are [offsets[i], offsets[i + 1])), with
// the data of every point and of every line. Lines are in vtkStreamTracer's order: with both
// directions, the forward lines of all seeds, then the backward lines of all seeds; every line
// starts at its seed.

#include <array>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <string>
#include <vector>

#include "column.hpp"
#include "precise_position.hpp"

namespace amrstream::flow {

// The box positions were wrapped into along its periodic axes (physical coordinates); a line
// that crosses a periodic face jumps by the period between two consecutive points.
struct PeriodicBox {
  std::array<bool, 3> axes{};
  glm::dvec3 lower{0.0}, upper{0.0};

  bool any() const { return axes[0] || axes[1] || axes[2]; }
  // Whether the segment a -> b crosses a periodic face (jumps by more than half a period).
  bool wraps(glm::dvec3 a, glm::dvec3 b) const {
    for (int axis = 0; axis < 3; ++axis)
      if (axes[axis] && std::abs(b[axis] - a[axis]) > 0.5 * (upper[axis] - lower[axis]))
        return true;
    return false;
  }
};

struct TraceSet {
  std::string vectorName;                 // e.g. "vel" for velx,vely,velz
  std::vector<std::string> channelNames;  // point-data channels, in the order of `channels`
  PeriodicBox periodic;

  // Per line.
  std::vector<std::uint32_t> seedIds;
  std::vector<float> directions;          // +1 forward, -1 backward
  std::vector<std::uint32_t> steps;       // integration steps the line took
  std::vector<std::int32_t> reasons;      // ReasonForTermination (trace_codes.h)
  std::vector<std::uint64_t> offsets{0};  // lineCount() + 1 entries, offsets[0] == 0

  // Per point.
  Column<glm::vec3> positions;     // physical coordinates
  Column<glm::vec3> positionsLow;  // one per point with precisePositions, else empty
  bool precisePositions = false;   // point i is at joinPosition(positions[i], positionsLow[i])
  Column<float> times;             // IntegrationTime: negative along backward lines
  bool timesAreAges = false;       // streaklines: times are the particles' ages at the end time
  Column<glm::vec3> vectors;       // the traced vector sampled at the point
  Column<float> channels;          // channelNames.size() values per point
  Column<glm::vec3> vorticity;     // one per point with withVorticity, else empty
  bool withVorticity = false;

  std::size_t lineCount() const { return seedIds.size(); }
  std::uint64_t pointCount() const { return offsets.empty() ? 0 : offsets.back(); }
  std::uint64_t pointCount(std::size_t line) const { return offsets[line + 1] - offsets[line]; }
  std::uint64_t firstPoint(std::size_t line) const { return offsets[line]; }
  std::size_t channelCount() const { return channelNames.size(); }

  // Host bytes per stored point: position, IntegrationTime, vector, channels, vorticity, and the
  // low part of a precise position.
  static std::size_t bytesPerPoint(std::size_t channelCount, bool vorticity,
                                   bool precisePositions = false) {
    return 2 * sizeof(glm::vec3) + sizeof(float) + channelCount * sizeof(float) +
           (vorticity ? sizeof(glm::vec3) : 0) + (precisePositions ? sizeof(glm::vec3) : 0);
  }
};

// A TraceSet with the names, periodic box and flags of `t` and no lines.
inline TraceSet shapeOf(const TraceSet& t) {
  TraceSet shape;
  shape.vectorName = t.vectorName;
  shape.channelNames = t.channelNames;
  shape.periodic = t.periodic;
  shape.precisePositions = t.precisePositions;
  shape.withVorticity = t.withVorticity;
  shape.timesAreAges = t.timesAreAges;
  return shape;
}

}  // namespace amrstream::flow
