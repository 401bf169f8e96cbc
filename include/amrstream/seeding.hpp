#pragma once
// Seeds as the command line's seeding options make them: a file, a rake, the densest cells of a
// scalar, a regular grid in a box, or random points in a box (the default: the whole domain).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "amrstream/dataset.hpp"
#include "flow/seed_strategies.hpp"
#include "flow/seeds.hpp"
#include "flow/vector_volume.hpp"

namespace amrstream {

// The first strategy set wins, in the order of the members.
struct SeedRequest {
  std::vector<glm::dvec3> points;  // given points (physical coordinates), e.g. from Python
  std::string file;                // one "x y z" per line
  std::vector<double> line;        // x0,y0,z0,x1,y1,z1: `count` seeds from one end to the other
  std::string density;             // a scalar: random points in cells at or above its percentile
  double percentile = 90.0;
  bool weighted = false;    // density: cells picked with probability proportional to it
  std::vector<int> grid;    // NX,NY,NZ: a regular grid in the box
  std::vector<double> box;  // x0,y0,z0,x1,y1,z1; empty: the domain
  std::size_t count = 256;
  std::uint64_t seed = 1;  // random seed
};

// The most seeds one request may make: lines are numbered in 32 bits, and each seed may make two
// (forward and backward).
inline constexpr std::uint64_t kMaxSeedCount = 2147483647;

// Throws InputError naming `option` when `count` seeds are more than kMaxSeedCount, or more than
// the machine's trace memory share (kTraceMemoryShare) can hold at the least each seed takes: the
// seed itself and one line of one point. Called before any seed is made.
void checkSeedCount(double count, const std::string& option);

// The box seeds may fill: the cells' bounding box [lower, upper) in physical coordinates.
struct Domain {
  glm::dvec3 lower{0.0}, upper{0.0};
  glm::dvec3 finestWidth{1.0};
  // When known, random seeds are drawn inside its cells, never in holes of the domain.
  const flow::VectorVolume* volume = nullptr;
};
Domain domainOf(const Dataset& cells);
Domain domainOf(const flow::VectorVolume& volume);

// checkSeedCount of the seeds the request makes (--count, or --seed-grid's NX x NY x NZ); given
// points and files are not checked.
void checkSeedRequest(const SeedRequest& request);

// The seeds and, in `description`, which strategy made them. Density seeding needs the cells.
// Throws InputError naming the option at fault, the request checked (checkSeedRequest) before any
// seed is made. `shared`: the cells' values are shared out among processes (MPI ranks over
// data), which choose density seeds together.
flow::SeedList chooseSeeds(const SeedRequest& request, const Domain& domain, const Dataset* cells,
                           std::string& description, const flow::SharedCells* shared = nullptr);

// Moves seeds on the domain's upper faces just inside (the domain is half-open) and throws
// InputError when a seed lies outside.
void placeSeeds(const flow::VectorVolume& volume, flow::SeedList& seeds);

}  // namespace amrstream
