#include "deep_nest.hpp"

#include "synth/nest_generator.hpp"

namespace amrstream::testing {

namespace {

// Cubes of 4 cells nest only as the middle 2 cells of the next coarser cube, so the centre is
// where the level-26 cube puts it: a multiple of 1/8 (here far from the middle 1/2), moved by a
// fraction of a finest cell off the cells' faces.
const glm::dvec3 kCentre = glm::dvec3(0.25, 0.625, 0.375) + 0.3 / double(1 << 30);

}  // namespace

bricks::AmrField deepNest() {
  synth::NestOptions nest;
  nest.levels = 28;
  nest.rootCells = 8;
  nest.blockCells = 4;
  nest.centre = kCentre;
  return synth::generateNest(nest);
}

std::vector<glm::dvec3> deepNestSeeds(const bricks::AmrField& nest) {
  const glm::dvec3 centre = kCentre / nest.transform().spacing;
  std::vector<glm::dvec3> seeds;
  for (const glm::dvec3 offset : {glm::dvec3(1.5, 0.25, 0.3), glm::dvec3(0.0, -3.0, 0.5),
                                  glm::dvec3(-6.0, 4.0, -1.0), glm::dvec3(12.0, 0.0, 2.0)})
    seeds.push_back(nest.transform().toPhysical(centre + offset));
  return seeds;
}

}  // namespace amrstream::testing
