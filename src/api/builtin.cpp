#include "amrstream/builtin.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "amrstream/dataset.hpp"
#include "amrstream/error.hpp"
#include "api/handles.hpp"
#include "synth/generators.hpp"
#include "synth/nest_generator.hpp"
#include "util/host_memory.hpp"

namespace amrstream {

namespace {

// The least a generated cell takes: its lower corner, its level and a 3-component vector.
constexpr double kLeastBytesPerCell = sizeof(glm::ivec3) + 1 + 3 * sizeof(float);

}  // namespace

std::vector<std::string> builtinKinds() { return synth::generatorKinds(); }

Dataset generateBuiltin(std::string_view kind, const BuiltinOptions& options) {
  return datasetOf(synth::generate(kind, options));
}

Dataset generateNest(const NestOptions& options) { return datasetOf(synth::generateNest(options)); }

double nestCellCount(const NestOptions& options) { return synth::nestCellCount(options); }

void checkGeneratedCells(double cells, const std::string& setting) {
  const double limit = kTraceMemoryShare * physicalMemoryBytes();
  if (limit > 0.0 && cells * kLeastBytesPerCell > limit)
    throw settingError(
        setting, fmt::format("{:.0f} cells need at least {:.1f} GiB ({:.0f} bytes each), more "
                             "than the {:.1f} GiB (3/4 of the memory) this machine allows",
                             cells, cells * kLeastBytesPerCell / 0x1p30, kLeastBytesPerCell,
                             limit / 0x1p30));
}

void checkBuiltinSize(const BuiltinOptions& options) {
  const double side =
      double(options.rootBlocks) * 8.0 * std::ldexp(1.0, std::max(0, options.levels - 1));
  checkGeneratedCells(std::min(double(options.targetCells), side * side * side), "target_cells");
}

}  // namespace amrstream
