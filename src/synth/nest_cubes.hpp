#pragma once
// The cubes of generateNest(), one per level, in 64-bit finest-cell units.

#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "nest_generator.hpp"

namespace amrstream::synth {

struct NestCube {
  int level = 0;
  glm::i64vec3 lower{0};   // finest-cell units, aligned to the next coarser level's cells
  std::int64_t cells = 0;  // per axis, each 2^level finest cells wide

  std::int64_t span() const { return cells << level; }
  glm::i64vec3 upper() const { return lower + span(); }
  bool contains(glm::i64vec3 p) const {
    return glm::all(glm::greaterThanEqual(p, lower)) && glm::all(glm::lessThan(p, upper()));
  }
};

// rootCells * 2^(levels-1).
std::int64_t nestFinestCellsPerAxis(const NestOptions& options);
// The centre in finest-cell units: centre * nestFinestCellsPerAxis().
glm::dvec3 nestCentreInCells(const NestOptions& options);

// Validates the options (generateNest() says how) and returns the cubes, the coarsest (the whole
// domain) first, each inside the one before it.
std::vector<NestCube> nestCubes(const NestOptions& options, const std::string& source);

}  // namespace amrstream::synth
