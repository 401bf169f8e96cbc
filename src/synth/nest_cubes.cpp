#include "nest_cubes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "amrstream/error.hpp"

namespace amrstream::synth {

namespace {

// Cells of the level above between a cube and the edge of the cube around it: one (proper
// nesting), none for an octree's cubes of 2 cells.
std::int64_t marginCells(int blockCells) { return blockCells == 2 ? 0 : 1; }

void validateNestOptions(const NestOptions& o, const std::string& source) {
  if (o.levels < 1 || o.levels > kMaxNestLevels)
    throw InputError(source, fmt::format("option levels is {}; it must be between 1 and {}",
                                         o.levels, kMaxNestLevels));
  if (o.blockCells < 2 || o.blockCells % 2 != 0)
    throw InputError(source, fmt::format("option blockCells is {}; it must be even and at least 2 "
                                         "(a finer cube is blockCells / 2 cells of the level "
                                         "above wide)",
                                         o.blockCells));
  const int leastRootCells =
      o.levels == 1 ? 1 : std::max(2, o.blockCells / 2 + 2 * int(marginCells(o.blockCells)));
  if (o.rootCells < leastRootCells)
    throw InputError(
        source,
        fmt::format(
            "option rootCells is {}; with {} levels and blockCells {} "
            "it must be at least {} (the next level's cube is {} root "
            "cells wide{}, and some root cells must stay leaves)",
            o.rootCells, o.levels, o.blockCells, leastRootCells, o.blockCells / 2,
            marginCells(o.blockCells) > 0 ? ", with one root cell of margin on each side" : ""));
  const std::int64_t axisLimit = std::int64_t(1) << bricks::kMaxExtentBits;
  if (nestFinestCellsPerAxis(o) > axisLimit)
    throw InputError(source,
                     fmt::format("option rootCells is {}; with {} levels the domain would "
                                 "span {} finest cells per axis, at most {} are supported",
                                 o.rootCells, o.levels, nestFinestCellsPerAxis(o), axisLimit));
  const double cellLimit = std::numeric_limits<std::int32_t>::max();
  if (synth::nestCellCount(o) > cellLimit)
    throw InputError(source,
                     fmt::format("options rootCells {} and blockCells {} make {:.0f} "
                                 "cells; at most {:.0f} are supported (cells are "
                                 "numbered in 32 bits)",
                                 o.rootCells, o.blockCells, synth::nestCellCount(o), cellLimit));
  const glm::dvec3 c = o.centre;
  if (!glm::all(glm::greaterThanEqual(c, glm::dvec3(0.0))) ||
      !glm::all(glm::lessThanEqual(c, glm::dvec3(1.0))))
    throw InputError(source, fmt::format("option centre is ({}, {}, {}); it must lie in the unit "
                                         "domain [0, 1]^3",
                                         c.x, c.y, c.z));
  for (const auto& [name, rate] :
       {std::pair{"rotationRate", o.rotationRate}, std::pair{"expansionRate", o.expansionRate}})
    if (!std::isfinite(rate))
      throw InputError(source, fmt::format("option {} is {}; it must be finite", name, rate));
  if (!(o.maxSpeed > 0.0))
    throw InputError(source, fmt::format("option maxSpeed is {}; it must be positive", o.maxSpeed));
}

// The cube of `level` centred on `centre` (finest-cell units), its lower corner rounded to the
// next coarser level's cells.
NestCube centredCube(int level, std::int64_t cells, glm::dvec3 centre) {
  const double coarseWidth = std::ldexp(1.0, level + 1);
  const double halfSpan = 0.5 * std::ldexp(double(cells), level);
  NestCube cube{level, glm::i64vec3(0), cells};
  for (int a = 0; a < 3; ++a)
    cube.lower[a] = std::llround((centre[a] - halfSpan) / coarseWidth) * (std::int64_t(2) << level);
  return cube;
}

void checkNested(const NestCube& inner, const NestCube& outer, const NestOptions& o,
                 const std::string& source) {
  const std::int64_t margin = marginCells(o.blockCells) << outer.level;
  for (int a = 0; a < 3; ++a) {
    if (inner.lower[a] >= outer.lower[a] + margin && inner.upper()[a] <= outer.upper()[a] - margin)
      continue;
    throw InputError(
        source,
        fmt::format("the nest cannot be centred on option centre ({}, {}, {}): the cube of "
                    "level {} (0 = finest) centred on it spans [{}, {}) finest cells "
                    "along {}, which must lie inside the level-{} cube [{}, {}) with {} finest "
                    "cells of margin; move the centre towards the domain's "
                    "middle, or raise rootCells or blockCells",
                    o.centre.x, o.centre.y, o.centre.z, inner.level, inner.lower[a],
                    inner.upper()[a], "xyz"[a], outer.level, outer.lower[a], outer.upper()[a],
                    margin));
  }
}

}  // namespace

std::int64_t nestFinestCellsPerAxis(const NestOptions& options) {
  return std::int64_t(options.rootCells) << (options.levels - 1);
}

glm::dvec3 nestCentreInCells(const NestOptions& options) {
  return options.centre * double(nestFinestCellsPerAxis(options));
}

std::vector<NestCube> nestCubes(const NestOptions& options, const std::string& source) {
  validateNestOptions(options, source);
  const glm::dvec3 centre = nestCentreInCells(options);
  std::vector<NestCube> cubes{{options.levels - 1, glm::i64vec3(0), options.rootCells}};
  for (int level = options.levels - 2; level >= 0; --level) {
    cubes.push_back(centredCube(level, options.blockCells, centre));
    checkNested(cubes.back(), cubes[cubes.size() - 2], options, source);
  }
  return cubes;
}

}  // namespace amrstream::synth
