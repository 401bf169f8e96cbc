#pragma once
// Seeds as the seeding settings make them: given points, a file, a rake, the densest cells of a
// scalar, a regular grid in a box, or random points in the cells of a box (the default: the whole
// domain).

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "amrstream/settings.hpp"

namespace amrstream {

class Dataset;
class Field;

// The first strategy set wins, in the order of the members; the comments name the settings of
// amrstream/settings.hpp.
struct SeedRequest {
  std::vector<glm::dvec3> points;  // given points (physical coordinates), e.g. from Python
  std::string file;                // seeds: one "x y z" per line
  std::vector<double> line;        // seed_line: x0,y0,z0,x1,y1,z1, `count` seeds from end to end
  std::string density;  // seed_density: random points in cells at or above its percentile
  double percentile = settings::kSeedPercentile.fallback;  // seed_percentile
  bool weighted = false;    // seed_weighted: cells picked with probability proportional to it
  std::vector<int> grid;    // seed_grid: NX,NY,NZ, a regular grid in the box
  std::vector<double> box;  // seed_box: x0,y0,z0,x1,y1,z1; empty: the domain
  std::size_t count = std::size_t(settings::kCount.fallback);    // count
  std::uint64_t seed = std::uint64_t(settings::kSeed.fallback);  // seed: the random seed
};

// The most seeds one request may make: lines are numbered in 32 bits, and each seed may make two
// (forward and backward).
inline constexpr std::uint64_t kMaxSeedCount = 2147483647;

// Throws InputError naming `setting` when `count` seeds are more than kMaxSeedCount, or more than
// the machine's trace memory share can hold at the least each seed takes: the seed itself and one
// line of one point. Called before any seed is made.
void checkSeedCount(double count, const std::string& setting);

// checkSeedCount of the seeds the request makes (count, or the grid's NX x NY x NZ); given points
// and files are not checked.
void checkSeedRequest(const SeedRequest& request);

// The seeds a request makes in a field's domain (random seeds inside its cells), and in
// `description` which strategy made them. Density seeding reads the field's dataset, which must
// be kept. Throws InputError naming the setting at fault.
std::vector<glm::dvec3> makeSeeds(const SeedRequest& request, const Field& field,
                                  std::string* description = nullptr);
// The same in a dataset's bounding box (random seeds in the box, not only in its cells).
std::vector<glm::dvec3> makeSeeds(const SeedRequest& request, const Dataset& dataset,
                                  std::string* description = nullptr);

}  // namespace amrstream
