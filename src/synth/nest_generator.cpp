#include "nest_generator.hpp"

#include <array>
#include <cstdint>
#include <vector>

#include "builtin_info.hpp"
#include "nest_cubes.hpp"
#include "spiral_field.hpp"

namespace amrstream::synth {

namespace {

struct LeafCell {
  glm::i64vec3 lower;
  int level;
};

// Each cube's cells outside the next finer cube, coarsest first, x fastest within a cube.
std::vector<LeafCell> leafCells(const std::vector<NestCube>& cubes) {
  std::vector<LeafCell> cells;
  for (std::size_t i = 0; i < cubes.size(); ++i) {
    const NestCube& cube = cubes[i];
    const std::int64_t width = std::int64_t(1) << cube.level;
    for (std::int64_t z = 0; z < cube.cells; ++z)
      for (std::int64_t y = 0; y < cube.cells; ++y)
        for (std::int64_t x = 0; x < cube.cells; ++x) {
          const glm::i64vec3 lower = cube.lower + width * glm::i64vec3(x, y, z);
          if (i + 1 < cubes.size() && cubes[i + 1].contains(lower)) continue;
          cells.push_back({lower, cube.level});
        }
  }
  return cells;
}

}  // namespace

double nestCellCount(const NestOptions& options) {
  const auto cubed = [](double n) { return n * n * n; };
  if (options.levels == 1) return cubed(options.rootCells);
  const double hole = cubed(options.blockCells / 2);
  return cubed(options.rootCells) + (options.levels - 1) * cubed(options.blockCells) -
         (options.levels - 1) * hole;
}

bricks::AmrField generateNest(const NestOptions& options) {
  const std::string source = "builtin:nest";
  const std::vector<LeafCell> cells = leafCells(nestCubes(options, source));
  const glm::dvec3 centre = nestCentreInCells(options);
  const double spacing = 1.0 / double(nestFinestCellsPerAxis(options));
  const SpiralField spiral{options.rotationRate, options.expansionRate};

  std::vector<glm::ivec3> lowers;
  std::vector<std::uint8_t> levels;
  std::array<std::vector<float>, 3> velocity;
  for (const LeafCell& cell : cells) {
    // The offset is taken in finest-cell units, where near the centre the subtraction is exact
    // (Sterbenz), and scaled after: the deepest cells keep every bit of their offset.
    const glm::dvec3 cellCentre = glm::dvec3(cell.lower) + 0.5 * std::ldexp(1.0, cell.level);
    glm::dvec3 v = spiral.velocity((cellCentre - centre) * spacing);
    if (const double speed = glm::length(v); speed > options.maxSpeed)
      v *= options.maxSpeed / speed;
    lowers.push_back(glm::ivec3(cell.lower));  // the options' check kept the domain in range
    levels.push_back(std::uint8_t(cell.level));
    for (int c = 0; c < 3; ++c) velocity[c].push_back(float(v[c]));
  }
  return bricks::AmrField(std::move(lowers), std::move(levels),
                          {{"velx", std::move(velocity[0])},
                           {"vely", std::move(velocity[1])},
                           {"velz", std::move(velocity[2])}},
                          {glm::dvec3(0.0), glm::dvec3(spacing)}, source,
                          builtinInfo(options.levels, options.time, false));
}

}  // namespace amrstream::synth
