#include "amrstream/dataset.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "formats/exa/exa_format.hpp"
#include "formats/load_input.hpp"
#include "util/input_error.hpp"

namespace amrstream {

Dataset load(const std::string& input, const synth::GeneratorOptions& builtin) {
  return formats::loadInput(input, builtin);
}

DeferredDataset loadDeferred(const std::string& input, const synth::GeneratorOptions& builtin) {
  if (formats::detectFormat(input) == formats::Format::ExaBricks) {
    formats::ExaCells exa = formats::readExaCells(input);
    DeferredDataset deferred{std::make_shared<Dataset>(std::move(exa.field)), {}, {}};
    deferred.catalog.source = deferred.cells->source();
    for (const formats::ExaChannelFile& file : exa.channels)
      deferred.catalog.names.push_back(file.name);
    deferred.channels = [files = std::move(exa.channels)](const std::string& name,
                                                          const flow::ChannelUse& use) {
      const auto file =
          std::find_if(files.begin(), files.end(), [&](const auto& f) { return f.name == name; });
      if (file == files.end())
        throw std::logic_error("loadDeferred: no channel '" + name + "' was listed");
      use(formats::readExaChannel(*file));
    };
    return deferred;
  }
  auto whole = std::make_shared<Dataset>(load(input, builtin));
  DeferredDataset deferred{whole, flow::catalogOf(*whole), {}};
  deferred.channels = [whole](const std::string& name, const flow::ChannelUse& use) {
    use(whole->channel(name).values);
  };
  return deferred;
}

Dataset fromCells(CellArrays cells) {
  if (cells.levels.size() != cells.corners.size())
    throw InputError(cells.source, fmt::format("{} levels for {} cells", cells.levels.size(),
                                               cells.corners.size()));
  if (cells.levels.empty()) throw InputError(cells.source, "no cells");
  const auto [lowest, highest] = std::minmax_element(cells.levels.begin(), cells.levels.end());
  if (*lowest < 0) throw InputError(cells.source, fmt::format("level {} is negative", *lowest));
  const int finest = *highest;
  if (finest - *lowest > bricks::kMaxLevel)
    throw InputError(cells.source, fmt::format("levels {}..{} span more than {} refinements",
                                               *lowest, finest, bricks::kMaxLevel));
  std::vector<std::uint8_t> levels(cells.levels.size());
  std::transform(cells.levels.begin(), cells.levels.end(), levels.begin(),
                 [finest](int level) { return static_cast<std::uint8_t>(finest - level); });
  if (!(glm::all(glm::greaterThan(cells.finestWidth, glm::dvec3(0.0))) &&
        glm::all(glm::lessThan(glm::abs(cells.origin), glm::dvec3(1e300)))))
    throw InputError(cells.source, "the finest cell width must be positive and the origin finite");

  bricks::DatasetInfo info;
  info.format = cells.format;
  info.time = cells.time;
  info.timeUnit = cells.timeUnit;
  info.lengthUnit = cells.lengthUnit;
  info.periodicKnown = cells.periodic.has_value();
  if (cells.periodic) info.periodic = *cells.periodic;
  info.finestFileLevel = finest;
  info.levelsCountDown = true;
  info.levelName = "level (0 = coarsest)";
  return Dataset(std::move(cells.corners), std::move(levels), std::move(cells.channels),
                 bricks::WorldTransform{cells.origin, cells.finestWidth}, cells.source,
                 std::move(info));
}

}  // namespace amrstream
