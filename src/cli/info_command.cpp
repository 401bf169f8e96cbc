#include "info_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <span>

#include "dataset_options.hpp"
#include "flow/vector_volume.hpp"
#include "formats/load_input.hpp"
#include "util/stopwatch.hpp"

namespace amrstream::cli {

namespace {

// The time with its unit, or what is missing.
std::string timeText(const bricks::DatasetInfo& info) {
  if (!info.time) return "unknown";
  return fmt::format("{:.9g} {}", *info.time,
                     info.timeUnit.empty() ? "(unit unknown)" : info.timeUnit);
}

// Cell counts per level, coarsest first, numbered as the file numbers its levels.
void printLevels(const bricks::AmrField& field) {
  const std::vector<std::size_t> perLevel = field.cellsPerLevel();
  const bricks::DatasetInfo& info = field.info();
  fmt::print("levels     {} used, numbered as {}; coarsest first, widths in finest cells\n",
             std::count_if(perLevel.begin(), perLevel.end(), [](std::size_t n) { return n > 0; }),
             info.levelName);
  for (int level = int(perLevel.size()) - 1; level >= 0; --level)
    if (perLevel[level] > 0)
      fmt::print("  level {:<3} {:>14} cells  width {}\n", info.fileLevel(level),
                 withCommas(perLevel[level]), bricks::AmrField::cellWidth(level));
}

void runInfo(const DatasetOptions& options) {
  checkBuiltinSize(options);
  Stopwatch clock;
  const bricks::AmrField field = formats::loadInput(options.input, options.generator);
  const bricks::DatasetInfo& info = field.info();
  fmt::print("input      {} [{:.2f} s]\n", field.source(), clock.seconds());
  fmt::print("format     {}\n", info.format.empty() ? "unknown" : info.format);
  fmt::print("time       {}\n", timeText(info));
  fmt::print("lengths    {}\n", info.lengthUnit.empty() ? "unit unknown" : info.lengthUnit);
  fmt::print("periodic   {}\n", bricks::periodicAxesText(info));
  fmt::print("cells      {}\n", withCommas(field.cellCount()));
  printLevels(field);

  const bricks::CellBox box = field.bounds();
  const bricks::WorldTransform& t = field.transform();
  const glm::dvec3 lo = t.toPhysical(glm::dvec3(box.lower)),
                   hi = t.toPhysical(glm::dvec3(box.upper));
  fmt::print("bounds     cells [{},{},{}] .. [{},{},{}] (finest-cell units)\n", box.lower.x,
             box.lower.y, box.lower.z, box.upper.x, box.upper.y, box.upper.z);
  fmt::print("           physical [{:g}, {:g}] x [{:g}, {:g}] x [{:g}, {:g}]\n", lo.x, hi.x, lo.y,
             hi.y, lo.z, hi.z);
  fmt::print("channels   {}\n", field.channels().size());
  for (const bricks::Channel& c : field.channels()) {
    const auto [min, max] = std::minmax_element(c.values.begin(), c.values.end());
    fmt::print("  {:<16} [{:g}, {:g}]\n", c.name, *min, *max);
  }

  flow::VolumeBuildTimes times;
  const flow::VectorVolume layout = flow::buildCellLayout(field, {}, &times);
  const std::span<const shared::Brick> bricks(layout.bricks);
  std::size_t maxCells = 0;
  for (const shared::Brick& b : bricks)
    maxCells = std::max<std::size_t>(maxCells, std::size_t(b.size.x) * b.size.y * b.size.z);
  fmt::print("bricks     {} (avg {:.1f} cells, max {}) built in {:.3f} s\n",
             withCommas(bricks.size()), double(field.cellCount()) / double(bricks.size()), maxCells,
             times.bricks);

  const bricks::RegionSet& regions = layout.regions;
  const double regionSeconds = times.regions;
  std::uint32_t maxBricks = 0;
  for (const shared::Region& r : regions.regions) maxBricks = std::max(maxBricks, r.brickCount);
  fmt::print("regions    {} (avg {:.2f} bricks, max {}; {} tree nodes) built in {:.3f} s\n",
             withCommas(regions.regions.size()),
             double(regions.regionBricks.size()) /
                 double(std::max<std::size_t>(1, regions.regions.size())),
             maxBricks, withCommas(regions.tree.size()), regionSeconds);
}

}  // namespace

void addInfoCommand(CLI::App& app) {
  auto options = std::make_shared<DatasetOptions>();
  CLI::App* command = app.add_subcommand("info", "describe a dataset and its bricks and regions");
  addDatasetOptions(*command, *options, "--gen-seed");
  command->callback([options] { runInfo(*options); });
}

}  // namespace amrstream::cli
