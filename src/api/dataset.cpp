#include "amrstream/dataset.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "amrstream/error.hpp"
#include "api/declared_units.hpp"
#include "api/handles.hpp"
#include "flow/vector_selection.hpp"
#include "formats/dataset_files.hpp"
#include "formats/exa/exa_format.hpp"
#include "formats/load_input.hpp"

namespace amrstream {

Dataset datasetOf(bricks::AmrField cells) {
  return Dataset(std::make_shared<const Dataset::Impl>(Dataset::Impl{std::move(cells)}));
}

Dataset::Dataset(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
const std::string& Dataset::source() const { return impl_->cells.source(); }
const DatasetInfo& Dataset::info() const { return impl_->cells.info(); }
std::size_t Dataset::cellCount() const { return impl_->cells.cellCount(); }
std::span<const glm::ivec3> Dataset::corners() const { return impl_->cells.lowers(); }
std::span<const std::uint8_t> Dataset::levels() const { return impl_->cells.levels(); }
std::vector<std::string> Dataset::channelNames() const {
  std::vector<std::string> names;
  for (const Channel& c : impl_->cells.channels()) names.push_back(c.name);
  return names;
}
bool Dataset::hasChannel(std::string_view name) const {
  return impl_->cells.findChannel(name).has_value();
}
std::span<const float> Dataset::channel(std::string_view name) const {
  return impl_->cells.channel(name).values;
}
const WorldTransform& Dataset::transform() const { return impl_->cells.transform(); }
CellBox Dataset::bounds() const { return impl_->cells.bounds(); }
std::pair<double, double> Dataset::checkSeconds() const {
  const bricks::AmrField::CheckSeconds seconds = impl_->cells.checkSeconds();
  return {seconds.cells, seconds.overlaps};
}
glm::dvec3 Dataset::lower() const { return transform().toPhysical(glm::dvec3(bounds().lower)); }
glm::dvec3 Dataset::upper() const { return transform().toPhysical(glm::dvec3(bounds().upper)); }
int Dataset::finestLevel() const { return impl_->cells.finestLevel(); }
int Dataset::coarsestLevel() const { return impl_->cells.coarsestLevel(); }
std::vector<std::size_t> Dataset::cellsPerLevel() const { return impl_->cells.cellsPerLevel(); }

Dataset load(const std::string& input, const BuiltinOptions& builtin, const DeclaredUnits& units) {
  bricks::AmrField cells = formats::loadInput(input, builtin);
  if (!units.empty()) {
    const flow::ChannelCatalog catalog = flow::catalogOf(cells);
    std::vector<std::string> names = catalog.names;
    try {
      names.push_back(flow::chooseVectorChannels(catalog, "").name);
    } catch (const InputError&) {  // no vector by default: the names are the channels
    }
    declareInputUnits(cells, units, names);
  }
  return datasetOf(std::move(cells));
}

std::vector<std::filesystem::path> datasetFiles(const std::string& input) {
  return formats::datasetFiles(input);
}

std::string formatName(const std::string& input) {
  return std::string(formats::formatName(formats::detectFormat(input)));
}

std::filesystem::path writeExaBricks(const Dataset& dataset, const std::filesystem::path& prefix) {
  return formats::writeExa(cellsOf(dataset), prefix);
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

  DatasetInfo info;
  info.format = cells.format;
  info.dimensions = cells.dimensions;
  info.time = cells.time;
  info.timeUnit = cells.timeUnit;
  info.lengthUnit = cells.lengthUnit;
  info.lengthUnitCentimetres = cells.lengthUnitCentimetres;
  info.units = cells.units;
  info.periodicKnown = cells.periodic.has_value();
  if (cells.periodic) info.periodic = *cells.periodic;
  info.finestFileLevel = finest;
  info.levelsCountDown = true;
  info.levelName = "level (0 = coarsest)";
  return datasetOf(bricks::AmrField(
      std::move(cells.corners), std::move(levels), std::move(cells.channels),
      WorldTransform{cells.origin, cells.finestWidth}, cells.source, std::move(info)));
}

}  // namespace amrstream
