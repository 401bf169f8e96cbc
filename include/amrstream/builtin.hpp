#pragma once
// Built-in synthetic datasets with known fields (builtin:KIND inputs and `amrstream gen`): the
// options that size them, and the datasets they make. Deterministic for given options.

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "amrstream/settings.hpp"

namespace amrstream {

class Dataset;

// The most levels a kind other than nest refines to, and nest's.
inline constexpr int kMaxBuiltinLevels = int(settings::kLevels.most);
inline constexpr int kMaxNestLevels = 30;
// Cells of a generated dataset are numbered in 32 bits.
inline constexpr std::uint64_t kMaxBuiltinCells = std::uint64_t(settings::kTargetCells.most);

// The settings of amrstream/settings.hpp the comments name.
struct BuiltinOptions {
  int levels = int(settings::kLevels.fallback);          // levels: 1 = uniform, at most 8 (nest 30)
  int rootBlocks = int(settings::kRootBlocks.fallback);  // root_blocks, each 8^3 coarsest cells
  std::size_t targetCells = std::size_t(settings::kTargetCells.fallback);  // target_cells
  std::uint64_t seed = std::uint64_t(settings::kGenSeed.fallback);         // gen_seed
  double time = settings::kTime.fallback;  // time: the snapshot's (unsteady kinds: swirl)
};

// A deep nest of cubes about one point with a spiral flow about it (kind nest).
struct NestOptions {
  int levels = 5;      // 1 to kMaxNestLevels
  int rootCells = 6;   // coarsest cells per axis; at least blockCells / 2 + 2 when levels > 1
                       // (2 for an octree)
  int blockCells = 8;  // cells per axis of each finer level's cube: even, at least 2
  // The nest's centre and the spiral's, as a fraction of the unit domain: off the domain's
  // middle, so the finest cells lie far from the coordinate origin and on no coarser cell face.
  // A cube must nest with its margin: with the default sizes each coordinate lies in about
  // [0.42, 0.58]; more root cells widen the range.
  glm::dvec3 centre{0.45, 0.55, 0.47};
  double rotationRate = 2.0 * std::numbers::pi;    // one turn per unit time
  double expansionRate = 0.5 * std::numbers::ln2;  // the offset from the centre doubles in 2 turns
  // Unit-domain lengths per unit time; the spiral's velocity is scaled down to it where faster.
  double maxSpeed = std::numeric_limits<double>::infinity();
  double time = 0.0;  // the snapshot's time in the DatasetInfo (the field is steady)
};

// rotation, abc, cloud, swirl, nest (docs/datasets.md describes each).
std::vector<std::string> builtinKinds();

// Throws InputError naming the kind and listing the kinds, or naming the option out of range.
Dataset generateBuiltin(std::string_view kind, const BuiltinOptions& options);
Dataset generateNest(const NestOptions& options);
// The cells generateNest makes, computed without making them.
double nestCellCount(const NestOptions& options);

// Throws InputError naming `setting` when `cells` generated cells cannot fit in the memory a run
// may take (3/4 of the machine's). Called before generating.
void checkGeneratedCells(double cells, const std::string& setting);
// The same for a kind's options: --target-cells, or all cells of fully refined levels if fewer.
void checkBuiltinSize(const BuiltinOptions& options);

}  // namespace amrstream
