#include "deep_nest.hpp"

#include "synth/nest_generator.hpp"

namespace amrstream::testing {

namespace {

constexpr double kFinestCellsPerAxis = double(1 << 30);

// Physical coordinates of points a few finest cells from the centre.
std::vector<glm::dvec3> seedsAbout(const bricks::AmrField& nest, glm::dvec3 centre) {
  const glm::dvec3 centreCells = centre / nest.transform().spacing;
  std::vector<glm::dvec3> seeds;
  for (const glm::dvec3 offset : {glm::dvec3(1.5, 0.25, 0.3), glm::dvec3(0.0, -3.0, 0.5),
                                  glm::dvec3(-6.0, 4.0, -1.0), glm::dvec3(12.0, 0.0, 2.0)})
    seeds.push_back(nest.transform().toPhysical(centreCells + offset));
  return seeds;
}

DeepNest build(const NestOptions& options) {
  bricks::AmrField field = synth::generateNest(options);
  std::vector<glm::dvec3> seeds = seedsAbout(field, options.centre);
  return {std::move(field), std::move(seeds)};
}

}  // namespace

DeepNest deepNest() {
  NestOptions nest;
  nest.levels = 28;
  nest.rootCells = 8;
  nest.blockCells = 4;
  // Cubes of 4 cells nest only as the middle 2 cells of the next coarser cube, so the centre is
  // where the level-26 cube puts it: a multiple of 1/8 (here far from the middle 1/2), moved by
  // a fraction of a finest cell off the cells' faces.
  nest.centre = glm::dvec3(0.25, 0.625, 0.375) + 0.3 / kFinestCellsPerAxis;
  return build(nest);
}

DeepNest deepOctreeNest() {
  NestOptions nest;
  nest.levels = 30;
  nest.rootCells = 2;
  nest.blockCells = 2;
  nest.centre = glm::dvec3(1.0 / 3.0, 2.0 / 3.0, 0.4);
  nest.maxSpeed = nest.rotationRate * 8.0 / kFinestCellsPerAxis;
  return build(nest);
}

}  // namespace amrstream::testing
