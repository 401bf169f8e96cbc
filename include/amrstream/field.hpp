#pragma once
// A dataset made ready for tracing: the vector and point-data channels chosen, periodic images
// added, bricks and active brick regions built, and the values laid out brick by brick.

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "amrstream/dataset.hpp"
#include "amrstream/settings.hpp"

namespace amrstream {

// The settings of amrstream/settings.hpp the comments name.
struct FieldOptions {
  // vector: "a,b,c", "grad(NAME)" or "-grad(NAME)"; empty: the velocity, else the magnetic field
  std::string vector;
  std::string pointData{settings::kPointData.shown};      // point_data
  std::string periodic{settings::kPeriodic.shown};        // periodic
  std::string interpolant{settings::kInterpolant.shown};  // interpolant
  std::string frameVelocity{};  // frame_velocity: "VX,VY,VZ" or "auto"; empty: none
};

// Seconds the field's parts took to build.
struct FieldBuildTimes {
  double bricks = 0.0, regions = 0.0, gradients = 0.0, gather = 0.0;
};

// A handle: copies share the field. The dataset it was built from stays with it when asked for
// (rendering colours tubes by its channels and shows its volume), else only what tracing reads.
class Field {
 public:
  const std::string& source() const;      // the dataset's name
  const DatasetInfo& info() const;        // what the dataset says of itself
  const std::string& vectorName() const;  // e.g. "vel", "grad(temp)"
  // e.g. velx, vely, velz; a gradient's d(temp)/dx, d(temp)/dy, d(temp)/dz
  const std::array<std::string, 3>& vectorChannels() const;
  // The velocity of the frame the vector is relative to (frame_velocity), subtracted from its
  // values; zero for none.
  glm::dvec3 frameVelocity() const;
  const std::vector<std::string>& pointDataNames() const;  // channels sampled along lines
  std::string periodicAxes() const;                        // "x,z"; empty for none
  std::string interpolant() const;                         // "tent" or "linear"
  std::size_t brickCount() const;      // the dataset's own, without periodic images
  std::size_t periodicImages() const;  // bricks added as periodic images
  std::size_t regionCount() const;
  glm::dvec3 lower() const;  // the domain, physical coordinates
  glm::dvec3 upper() const;
  const FieldBuildTimes& buildTimes() const;
  // The dataset it was built from, where kept (KeepDataset).
  const std::optional<Dataset>& dataset() const;

  struct Impl;  // the library's: src/api/handles.hpp
  explicit Field(std::shared_ptr<Impl> impl);
  Impl& impl() const { return *impl_; }

 private:
  std::shared_ptr<Impl> impl_;
};

// Whether a Field keeps the Dataset it was built from (rendering reads its channels) or only what
// tracing reads.
enum class KeepDataset { No, Yes };

// Throws InputError naming the missing channel or the bad option. frame_velocity auto takes the
// mean of the vector over the cells that hold `seeds` (physical coordinates), or over the whole
// domain where none are given.
Field buildField(const Dataset& cells, const FieldOptions& options,
                 KeepDataset keep = KeepDataset::Yes, std::span<const glm::dvec3> seeds = {});

}  // namespace amrstream
