#pragma once
// Seeds as a SeedRequest makes them (amrstream/seeding.hpp), in a domain: the strategies' seeds
// with the text naming each seed's origin, for the library's jobs and the Python module.

#include <string>

#include "amrstream/seeding.hpp"
#include "bricks/amr_field.hpp"
#include "flow/seed_strategies.hpp"
#include "flow/seeds.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

// The box seeds may fill: the cells' bounding box [lower, upper) in physical coordinates.
struct Domain {
  glm::dvec3 lower{0.0}, upper{0.0};
  glm::dvec3 finestWidth{1.0};
  // When known, random seeds are drawn inside its cells, never in holes of the domain.
  const flow::VectorVolume* volume = nullptr;
  bool planar = false;  // 2D data: seeds go onto the plane in the middle of the slab
};
Domain domainOf(const bricks::AmrField& cells);
Domain domainOf(const flow::VectorVolume& volume);

// The seeds and, in `description`, which strategy made them. Density seeding needs the cells.
// Throws InputError naming the option at fault, the request checked (checkSeedRequest) before any
// seed is made. `shared`: the cells' values are shared out among processes (MPI ranks over
// data), which choose density seeds together.
flow::SeedList chooseSeeds(const SeedRequest& request, const Domain& domain,
                           const bricks::AmrField* cells, std::string& description,
                           const flow::SharedCells* shared = nullptr);

// Moves seeds on the domain's upper faces just inside (the domain is half-open) and throws
// InputError when a seed lies outside.
void placeSeeds(const flow::VectorVolume& volume, flow::SeedList& seeds);

}  // namespace amrstream
