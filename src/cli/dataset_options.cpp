#include "dataset_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>

#include "option_checks.hpp"
#include "option_limits.hpp"
#include "synth/block_refiner.hpp"
#include "util/host_memory.hpp"
#include "util/input_error.hpp"

namespace amrstream::cli {

namespace {

// The least a generated cell takes: its lower corner, its level and a 3-component vector.
constexpr double kLeastBytesPerCell = sizeof(glm::ivec3) + 1 + 3 * sizeof(float);

}  // namespace

void addGeneratorOptions(CLI::App& command, synth::GeneratorOptions& options,
                         const std::string& seedFlag, int maxLevels) {
  command.add_option("--levels", options.levels, "AMR levels of a generated dataset")
      ->capture_default_str()
      ->check(countIn(1, maxLevels));
  command
      .add_option("--root-blocks", options.rootBlocks,
                  "root blocks (of 8^3 cells) per axis of a generated dataset")
      ->capture_default_str()
      ->check(countIn(1, std::numeric_limits<int>::max()));
  command.add_option("--target-cells", options.targetCells, "cell budget of a generated dataset")
      ->capture_default_str()
      ->check(countIn(1, kMaxTargetCells));
  command.add_option(seedFlag, options.seed, "random seed of a generated dataset")
      ->capture_default_str()
      ->check(countIn(0, std::numeric_limits<std::uint64_t>::max()));
  command
      .add_option("--time", options.time, "snapshot time of a generated unsteady dataset (swirl)")
      ->capture_default_str()
      ->check(finiteDouble());
}

void checkGeneratorSize(const synth::GeneratorOptions& generator) {
  const double side =
      double(generator.rootBlocks) * 8.0 * std::ldexp(1.0, std::max(0, generator.levels - 1));
  checkGeneratedCells(std::min(double(generator.targetCells), side * side * side),
                      "--target-cells");
}

void checkGeneratedCells(double cells, const std::string& option) {
  const double limit = kTraceMemoryShare * physicalMemoryBytes();
  if (limit > 0.0 && cells * kLeastBytesPerCell > limit)
    throw InputError(option,
                     fmt::format("{:.0f} cells need at least {:.1f} GiB ({:.0f} bytes each), more "
                                 "than the {:.1f} GiB (3/4 of the memory) this machine allows",
                                 cells, cells * kLeastBytesPerCell / 0x1p30, kLeastBytesPerCell,
                                 limit / 0x1p30));
}

void checkBuiltinSize(const DatasetOptions& options) {
  if (options.input.starts_with("builtin:")) checkGeneratorSize(options.generator);
}

void addDatasetOptions(CLI::App& command, DatasetOptions& options, const std::string& seedFlag) {
  std::string kinds;
  for (const std::string& kind : synth::generatorKinds())
    kinds += (kinds.empty() ? "" : "|") + kind;
  command
      .add_option("input", options.input,
                  "the dataset: a FLASH HDF5 plotfile or checkpoint, an Enzo parameter file (or "
                  "its .hierarchy, .harrays or .cpuNNNN), an AMReX plotfile directory, a Gerris "
                  "text dump, an ExaBricks .exa file, or builtin:" +
                      kinds)
      ->required();
  addGeneratorOptions(command, options.generator, seedFlag, synth::kMaxGeneratorLevels);
}

std::string withCommas(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

}  // namespace amrstream::cli
