#pragma once
// The frame the vector is measured in (frame_velocity): its velocity as given, or `auto`, the
// mean of the vector over the job's seeding region (flow/frame_velocity.hpp), and the summary's
// line that says which velocity was used.

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>

#include "amrstream/seeding.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

struct FrameChoice {
  bool given = false;      // a frame was asked for
  bool automatic = false;  // auto: its velocity comes from the field and the seeding region
  glm::dvec3 velocity{0.0};
};

// `text` is empty (no frame), "auto" or VX,VY,VZ (three finite numbers). Throws InputError
// naming {frame_velocity} otherwise.
FrameChoice parseFrameVelocity(const std::string& text);

// Where auto takes the mean, in `layout`'s cell units, and `description` says it: the seed box
// of random and grid seeding (the request's, else the domain), or the cells that hold the seeds
// of the other strategies (given points, a file, a rake, density seeding).
flow::FrameRegion seedingRegion(const SeedRequest& request, std::span<const glm::dvec3> seeds,
                                const flow::VectorVolume& layout, std::string& description);
// The whole domain of `layout`, or the cells that hold `points` (physical coordinates) where
// there are some.
flow::FrameRegion pointsRegion(std::span<const glm::dvec3> points, const flow::VectorVolume& layout,
                               std::string& description);

// " relative to a frame moving at (0.6, 0.6, 0.6)" for a volume with a frame velocity; empty
// otherwise.
std::string relativeToFrame(const flow::VectorVolume& volume);

// "frame      vel relative to a frame moving at (0.6, 0.6, 0.6)", with for auto what the mean
// was taken over (`region`); none where no frame was asked for.
std::optional<std::string> frameLine(const FrameChoice& frame, const flow::VectorVolume& volume,
                                     const std::string& region);

}  // namespace amrstream
