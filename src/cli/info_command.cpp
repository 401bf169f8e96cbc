#include "info_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>

#include "amrstream/dataset.hpp"
#include "amrstream/log.hpp"
#include "amrstream/stage_clock.hpp"
#include "console.hpp"
#include "dataset_options.hpp"

namespace amrstream::cli {

namespace {

// The time with its unit, or what is missing.
std::string timeText(const DatasetInfo& info) {
  if (!info.time) return "unknown";
  return fmt::format("{:.9g} {}", *info.time,
                     info.timeUnit.empty() ? "(unit unknown)" : info.timeUnit);
}

// Cell counts per level, coarsest first, numbered as the file numbers its levels.
void printLevels(const Dataset& dataset) {
  const std::vector<std::size_t> perLevel = dataset.cellsPerLevel();
  const DatasetInfo& info = dataset.info();
  std::string covered;  // the file's levels wholly under finer cells
  for (int level = int(perLevel.size()) - 1; level >= 0; --level) {
    if (perLevel[level] == 0) continue;
    const int coarsestLeaf = info.fileLevel(level);
    if (info.rootFileLevel && info.levelsCountDown && coarsestLeaf > *info.rootFileLevel)
      covered = fmt::format(" (the file's levels {} to {} lie wholly under finer cells)",
                            *info.rootFileLevel, coarsestLeaf - 1);
    break;
  }
  printLine(fmt::format(
      "levels     {} hold leaf cells{}, numbered as {}; coarsest first, widths in finest cells",
      std::count_if(perLevel.begin(), perLevel.end(), [](std::size_t n) { return n > 0; }), covered,
      info.levelName));
  for (int level = int(perLevel.size()) - 1; level >= 0; --level)
    if (perLevel[level] > 0)
      printLine(fmt::format("  level {:<3} {:>14} cells  width {}", info.fileLevel(level),
                            withCommas(perLevel[level]), 1 << level));
}

// The finest cell's size, said anisotropic where its sides differ, and the axes one cell thick.
void printShape(const CellBox& box, glm::dvec3 finest, int declaredDimensions) {
  const double shortest = std::min({finest.x, finest.y, finest.z});
  const double longest = std::max({finest.x, finest.y, finest.z});
  printLine(fmt::format("finest     cell {:g} x {:g} x {:g}{}", finest.x, finest.y, finest.z,
                        longest > shortest * (1.0 + 1e-6)
                            ? fmt::format(" (anisotropic: {:.3g} to 1)", longest / shortest)
                            : ""));
  if (declaredDimensions == 2) {
    const int thickness = box.upper.z - box.lower.z;
    printLine(
        fmt::format("dimensions 2: planar data, held as a slab {} finest cell{} thick across "
                    "z = 0",
                    thickness, thickness == 1 ? "" : "s"));
    return;
  }
  std::string flat;
  int dimensions = 3;
  for (int axis = 0; axis < 3; ++axis)
    if (box.upper[axis] - box.lower[axis] == 1) {
      flat += (flat.empty() ? "" : ", ") + std::string(1, "xyz"[axis]);
      --dimensions;
    }
  if (!flat.empty())
    printLine(fmt::format("dimensions {}: one finest cell thick in {}", dimensions, flat));
}

void printStructure(const Dataset& dataset, const DatasetSummary& s) {
  printLine(fmt::format("bricks     {} (avg {:.1f} cells, max {}) built in {:.3f} s",
                        withCommas(s.bricks), double(dataset.cellCount()) / double(s.bricks),
                        s.largestBrickCells, s.bricksSeconds));
  printLine(
      fmt::format("regions    {} (avg {:.2f} bricks, max {}; {} tree nodes) built in {:.3f} s",
                  withCommas(s.regions),
                  double(s.regionBrickEntries) / double(std::max<std::size_t>(1, s.regions)),
                  s.largestRegionBricks, withCommas(s.treeNodes), s.regionsSeconds));
}

// Describes the dataset and says how long each stage took (the "structure" summary's bricks
// and regions are built here to be counted).
void describe(const DatasetRequest& request, StageClock& clock) {
  const auto start = std::chrono::steady_clock::now();
  const Dataset dataset = load(request.input, request.builtin, request.units);
  const auto [cellChecks, overlapCheck] = dataset.checkSeconds();
  clock.lap("input", {{"cell checks", cellChecks}, {"overlap check", overlapCheck}});
  const DatasetInfo& info = dataset.info();
  printLine(
      fmt::format("input      {} [{:.2f} s]", dataset.source(),
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()));
  printLine(fmt::format("format     {}", info.format.empty() ? "unknown" : info.format));
  printLine(fmt::format("time       {}", timeText(info)));
  printLine(
      fmt::format("lengths    {}", info.lengthUnit.empty() ? "unit unknown" : info.lengthUnit));
  printLine(fmt::format("periodic   {}", periodicAxesText(info)));
  printLine(fmt::format("cells      {}", withCommas(dataset.cellCount())));
  printLevels(dataset);

  const CellBox box = dataset.bounds();
  const glm::dvec3 lo = dataset.lower(), hi = dataset.upper();
  printLine(fmt::format("bounds     cells [{},{},{}] .. [{},{},{}] (finest-cell units)",
                        box.lower.x, box.lower.y, box.lower.z, box.upper.x, box.upper.y,
                        box.upper.z));
  printLine(fmt::format("           physical [{:g}, {:g}] x [{:g}, {:g}] x [{:g}, {:g}]", lo.x,
                        hi.x, lo.y, hi.y, lo.z, hi.z));
  printShape(box, (hi - lo) / glm::dvec3(box.upper - box.lower), info.dimensions);
  clock.lap("describing");
  const DatasetSummary summary = summarize(dataset);
  clock.lap("summary", {{"bricks", summary.bricksSeconds}, {"regions", summary.regionsSeconds}});
  printLine(fmt::format("channels   {}", summary.channels.size()));
  for (const DatasetSummary::ChannelRange& c : summary.channels) {
    const std::string unit = unitOf(info, c.name);
    printLine(fmt::format("  {:<16} [{:g}, {:g}]{}{}", c.name, c.min, c.max,
                          unit.empty() ? "" : " ", unit));
  }
  printStructure(dataset, summary);
}

void runInfo(const DatasetRequest& request) {
  if (request.input.starts_with("builtin:")) checkBuiltinSize(request.builtin);
  StageClock clock;
  describe(request, clock);
  clock.lap("freeing");
  printLine(clock.line());
}

}  // namespace

void addInfoCommand(CLI::App& app) {
  auto options = std::make_shared<DatasetRequest>();
  CLI::App* command = app.add_subcommand("info", "describe a dataset and its bricks and regions");
  addDatasetOptions(*command, *options, "--gen-seed");
  command->callback([options] { runInfo(*options); });
}

}  // namespace amrstream::cli
