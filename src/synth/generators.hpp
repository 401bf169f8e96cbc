#pragma once
// Synthetic AMR datasets with known fields, for tests, the built-in dataset and benchmarks.
// Every generator refines 8^3-cell blocks (an octree of blocks over a root grid of blocks) where
// its refinement criterion is largest, until the cell budget or the level limit is reached.
// Deterministic for given options.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "amrstream/builtin.hpp"
#include "bricks/amr_field.hpp"

namespace amrstream::synth {

// Kinds: "rotation" (solid-body rotation about the z axis through the domain centre, channels
// velx vely velz), "abc" (Arnold-Beltrami-Childress flow, velx vely velz), "cloud" (magnetised
// filament cloud: dens, magx magy magz), "swirl" (unsteady: a pulsing rotation with a vertical
// drift at options.time, refined around a feature the flow carries, so refinement moves between
// times; velx vely velz temp; swirl_field.hpp), "nest" (generateNest() with options.levels and
// options.time and its other defaults, the other options unused: a deep nest of cubes about an
// off-centre point with a spiral flow about it; velx vely velz; nest_generator.hpp). Throws
// InputError naming the kind and listing the kinds. DatasetInfo: format "builtin", time
// options.time (0 for the steady kinds), units unknown (dimensionless), periodic on every axis for
// abc (one full period over the unit cube) and on none for the others, levels numbered 0 = the
// root blocks' (coarsest) level up to levels - 1.
bricks::AmrField generate(std::string_view kind, const BuiltinOptions& options);
std::vector<std::string> generatorKinds();

}  // namespace amrstream::synth
