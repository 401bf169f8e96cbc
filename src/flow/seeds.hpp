#pragma once
// Seed points in the input's physical coordinates, where they came from, and their checks.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "vector_volume.hpp"

namespace amrstream::flow {

struct SeedList {
  std::vector<glm::dvec3> points;
  // Where point i came from, for errors ("seeds.txt:12", "random seed #3"), made only when an
  // error names a point: millions of seeds cost no strings. Empty: "seed #i".
  std::function<std::string(std::size_t)> origin;
  std::string originOf(std::size_t i) const;
};

// One "x y z" per line, separated by spaces, tabs or commas; '#' starts a comment; blank lines
// are skipped. Throws InputError naming the file and line of anything else, and naming the file
// when it is no regular file (a FIFO or a device is refused before it is opened), larger than
// 3/4 of the memory, or changes while it is read. output::writeSeedFile writes this format.
SeedList readSeedFile(const std::filesystem::path& path);

// `count` points uniformly distributed in [lower, upper), reproducible for a given `seed`.
SeedList randomSeedsInBox(glm::dvec3 lower, glm::dvec3 upper, std::size_t count,
                          std::uint64_t seed);

// Physical bounds of the volume's domain.
glm::dvec3 domainLower(const VectorVolume& volume);
glm::dvec3 domainUpper(const VectorVolume& volume);

// Seeds on the domain's upper faces, which the half-open domain [lower, upper) leaves out, moved
// inside by 1e-4 of a finest cell: users give the domain's corners as rake ends and grid bounds.
void closeUpperFaces(const VectorVolume& volume, SeedList& seeds);

// Throws InputError naming the first seed outside the domain (outside the cells' bounding box or
// in empty space between them), with its origin and the domain bounds.
void checkSeedsInDomain(const VectorVolume& volume, const SeedList& seeds);

}  // namespace amrstream::flow
