#include "api/frame_choice.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "amrstream/error.hpp"
#include "flow/value_range.hpp"

namespace amrstream {

namespace {

// `part` as a whole finite number.
std::optional<double> finiteNumber(const std::string& part) {
  if (part.empty() || std::isspace(static_cast<unsigned char>(part.front()))) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(part.c_str(), &end);
  if (end != part.c_str() + part.size() || errno == ERANGE || !std::isfinite(value))
    return std::nullopt;
  return value;
}

}  // namespace

FrameChoice parseFrameVelocity(const std::string& text) {
  FrameChoice frame;
  if (text.empty()) return frame;
  frame.given = true;
  if (text == "auto") {
    frame.automatic = true;
    return frame;
  }
  std::vector<std::string> parts;
  std::istringstream list(text);
  for (std::string part; std::getline(list, part, ',');) parts.push_back(part);
  if (parts.size() != 3 || text.back() == ',')
    throw settingError("frame_velocity",
                       fmt::format("'{}' is not auto nor three numbers VX,VY,VZ", text));
  for (int axis = 0; axis < 3; ++axis) {
    const std::optional<double> value = finiteNumber(parts[std::size_t(axis)]);
    if (!value || std::abs(*value) > double(flow::kMaxVectorComponent))
      throw settingError("frame_velocity",
                         fmt::format("'{}' in '{}' is not a finite number within +-{:g}",
                                     parts[std::size_t(axis)], text, flow::kMaxVectorComponent));
    frame.velocity[axis] = *value;
  }
  return frame;
}

flow::FrameRegion pointsRegion(std::span<const glm::dvec3> points, const flow::VectorVolume& layout,
                               std::string& description) {
  flow::FrameRegion region;
  if (points.empty()) {
    description = "the domain";
    region.box =
        flow::FrameRegion::Box{glm::dvec3(layout.domain.lower), glm::dvec3(layout.domain.upper)};
    return region;
  }
  description = "the cells that hold the seeds";
  for (const glm::dvec3& p : points) region.points.push_back(layout.transform.toCellUnits(p));
  return region;
}

flow::FrameRegion seedingRegion(const SeedRequest& request, std::span<const glm::dvec3> seeds,
                                const flow::VectorVolume& layout, std::string& description) {
  const bool seedBox = request.points.empty() && request.file.empty() && request.line.empty() &&
                       request.density.empty();
  if (!seedBox) return pointsRegion(seeds, layout, description);
  if (request.box.size() != 6) return pointsRegion({}, layout, description);
  description = "the seed box";
  const WorldTransform& t = layout.transform;
  return {flow::FrameRegion::Box{t.toCellUnits({request.box[0], request.box[1], request.box[2]}),
                                 t.toCellUnits({request.box[3], request.box[4], request.box[5]})},
          {}};
}

namespace {

std::string movingAt(glm::dvec3 v) {
  return fmt::format("relative to a frame moving at ({:.6g}, {:.6g}, {:.6g})", v.x, v.y, v.z);
}

}  // namespace

std::string relativeToFrame(const flow::VectorVolume& volume) {
  return volume.frameVelocity == glm::dvec3(0.0) ? std::string()
                                                 : " " + movingAt(volume.frameVelocity);
}

std::optional<std::string> frameLine(const FrameChoice& frame, const flow::VectorVolume& volume,
                                     const std::string& region) {
  if (!frame.given) return std::nullopt;
  return fmt::format("frame      {} {}{}", volume.vectorName, movingAt(volume.frameVelocity),
                     frame.automatic
                         ? fmt::format(": auto, the mean of {} over {}, weighted by cell volume",
                                       volume.vectorName, region)
                         : std::string());
}

}  // namespace amrstream
